#include "shadows/screen/screen_march.h"

#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "scenes/camera.h"
#include "shading/lights.h"

namespace shadowlab {
namespace {

static_assert(int(MarchEnd::Lit) == kMarchLit && int(MarchEnd::Occluded) == kMarchOccluded &&
              int(MarchEnd::LeftScreen) == kMarchLeftScreen);
// The G-buffer's vectors are read as packed x, y, z floats.
static_assert(sizeof(glm::vec3) == 3 * sizeof(float));

MarchKernels marchKernels(raster::SimdLevel simd) {
    return raster::forSimdLevel(simd, marchKernelsScalar, marchKernelsAvx2, marchKernelsAvx512);
}

void copy3(float* to, const glm::vec3& v) { to[0] = v.x, to[1] = v.y, to[2] = v.z; }

}  // namespace

ScreenMarch::ScreenMarch(const GBuffer& g, const Camera& camera, const Light& pointLight, const MarchSettings& settings)
    : g_(g), light_(pointLight), constants_{}, surfaces_{} {
    // The kernels index pixels, and the triples' floats, in int32.
    if (g.pixelCount() > size_t(INT32_MAX / 3)) throw std::invalid_argument("contact-shadows: the image is too large");
    MarchConstants& c = constants_;
    const glm::mat4 clip = clipFromWorld(camera);
    for (int k = 0; k < 16; ++k) c.clipFromWorld[k] = glm::value_ptr(clip)[k];
    copy3(c.eye, camera.eye);
    copy3(c.forward, glm::normalize(camera.target - camera.eye));
    c.zNear = camera.zNear;
    c.pixelFootprint = 2.0f / (clipFromView(camera)[1][1] * float(camera.height));
    c.width = g.width, c.height = g.height;
    c.directional = pointLight.type == LightType::Directional;
    copy3(c.light, c.directional ? pointLight.direction : pointLight.position);
    c.lengthM = settings.lengthM, c.steps = settings.steps, c.thicknessM = settings.thicknessM;
    const float* P = reinterpret_cast<const float*>(g.position.data());
    const float* N = reinterpret_cast<const float*>(g.normal.data());
    surfaces_ = {{P, P + 1, P + 2, N, N + 1, N + 2}, 3};
}

std::vector<MarchSample> ScreenMarch::samples(size_t k) const {
    const size_t steps = size_t(constants_.steps);
    std::vector<float> distance(steps), x(steps), y(steps), depth(steps), buffer(steps);
    std::vector<uint32_t> occluded(steps);
    uint32_t count = 0;
    const uint8_t active = 1;
    marchKernelsScalar().trace(constants_, surfaces_, {&active, int(k), 1},
                               {distance.data(), x.data(), y.data(), depth.data(), buffer.data(), occluded.data(), &count});
    std::vector<MarchSample> out(count);
    for (size_t n = 0; n < count; ++n) {
        out[n] = {distance[n], {x[n], y[n]}, depth[n], buffer[n], occluded[n] != 0};
    }
    return out;
}

ScreenMarch::Mask ScreenMarch::mask(raster::SimdLevel simd) const {
    Mask out{std::vector<float>(g_.pixelCount()), std::vector<uint8_t>(g_.pixelCount())};
    const LightReach reaches(light_);
    const MarchKernels vector = marchKernels(simd), scalar = marchKernelsScalar();
    const int width = g_.width, vectors = width - width % vector.width;
    const size_t rowLength = size_t(width);
    tbb::parallel_for(tbb::blocked_range<int>(0, g_.height), [&](const tbb::blocked_range<int>& rows) {
        std::vector<uint8_t> active(rowLength);   // per task: whether each pixel of a row marches
        for (int j = rows.begin(); j < rows.end(); ++j) {
            const size_t k = g_.index(0, j);
            for (int i = 0; i < width; ++i) {
                active[size_t(i)] = g_.hit[k + size_t(i)] && reaches(g_.position[k + size_t(i)], g_.normal[k + size_t(i)]);
            }
            // The row's tail, fewer pixels than a vector, goes through the scalar twin (the same bits).
            const auto run = [&](const MarchKernels& kernels, int from, int count) {
                kernels.mask(constants_, surfaces_, {active.data() + from, int(k) + from, count},
                             {out.end.data() + k + size_t(from), out.visibility.data() + k + size_t(from)});
            };
            run(vector, 0, vectors);
            run(scalar, vectors, width - vectors);
        }
    });
    return out;
}

}  // namespace shadowlab
