// numpy arrays that view a buffer of the library without copying it: the array's base is the
// Python object that owns the buffer, so the buffer lives as long as any view of it.
#pragma once

#include <type_traits>
#include <vector>

#include <glm/glm.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace shadowlab::python {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::vec2) == 2 * sizeof(float),
              "a vector of glm::vec3 is viewed as rows of 3 floats");

// A (height, width) view of one value per pixel, or None for an empty buffer (a buffer the
// frame does not have).
template <class T>
    requires std::is_arithmetic_v<T>
pybind11::object bufferView(const pybind11::handle& owner, std::vector<T>& values, int width, int height) {
    if (values.empty()) return pybind11::none();
    return pybind11::array_t<T>({height, width}, values.data(), owner);
}

// A (height, width, N) view of glm vectors of N floats per pixel, or None for an empty buffer.
template <glm::length_t N>
pybind11::object bufferView(const pybind11::handle& owner, std::vector<glm::vec<N, float>>& values, int width,
                            int height) {
    if (values.empty()) return pybind11::none();
    constexpr int n = int(N);
    return pybind11::array_t<float>({height, width, n}, reinterpret_cast<float*>(values.data()), owner);
}

}  // namespace shadowlab::python
