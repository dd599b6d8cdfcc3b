#include "differential/scene/compositing_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "raster/portable_math.h"
#include "scenes/float_range.h"

namespace shadowlab {
namespace {

void requireValid(const PatchSurface& s) {
    const std::string who = "compositing scene: surface '" + s.name + "' ";
    if (!allFinite(s.origin)) throw std::invalid_argument(who + "has a non-finite origin");
    const double area = glm::length(glm::cross(s.edgeU, s.edgeV));
    if (!(area > 0.0) || !std::isfinite(area)) throw std::invalid_argument(who + "has no area");
    if (s.cellsU < 1 || s.cellsV < 1 || s.cellsU > 4096 || s.cellsV > 4096) {
        throw std::invalid_argument(who + "needs 1 to 4096 cells per side");
    }
    for (int c = 0; c < 3; ++c) {
        if (!(s.reflectance[c] >= 0.0 && s.reflectance[c] < 1.0)) {
            throw std::invalid_argument(who + "has a reflectance outside [0, 1)");
        }
    }
    const size_t cells = size_t(s.cellsU) * size_t(s.cellsV);
    if (s.emitted.size() > 1 && s.emitted.size() != cells) {
        throw std::invalid_argument(who + "needs 1 or cellsU * cellsV emitted radiances");
    }
    for (const glm::dvec3& L : s.emitted) {
        for (int c = 0; c < 3; ++c) {
            if (!(L[c] >= 0.0) || !std::isfinite(L[c])) throw std::invalid_argument(who + "has a bad emitted radiance");
        }
    }
}

}  // namespace

std::array<glm::dvec3, 4> PatchModel::corners(uint32_t p) const {
    const Patch& patch = patches[p];
    return {vertices[patch.vertex[0]], vertices[patch.vertex[1]], vertices[patch.vertex[2]], vertices[patch.vertex[3]]};
}

glm::dvec3 PatchModel::pointAt(uint32_t p, double u, double v) const {
    // Grid cells are parallelograms: v0 + u (v1 - v0) + v (v3 - v0).
    const std::array<glm::dvec3, 4> c = corners(p);
    return c[0] + u * (c[1] - c[0]) + v * (c[3] - c[0]);
}

PatchModel flattenPatches(const std::vector<PatchSurface>& surfaces) {
    size_t patches = 0;
    for (const PatchSurface& surface : surfaces) {
        requireValid(surface);
        patches += size_t(surface.cellsU) * size_t(surface.cellsV);
    }
    if (patches > kMaxCompositingPatches) {
        throw std::invalid_argument("compositing scene: " + std::to_string(patches) + " patches, more than " +
                                    std::to_string(kMaxCompositingPatches));
    }
    PatchModel model;
    for (uint32_t s = 0; s < surfaces.size(); ++s) {
        const PatchSurface& surface = surfaces[s];
        const glm::dvec3 normal = glm::normalize(glm::cross(surface.edgeU, surface.edgeV));
        const uint32_t first = uint32_t(model.vertices.size());
        const glm::dvec3 centre = surface.origin + 0.5 * (surface.edgeU + surface.edgeV);
        const int nu = surface.cellsU, nv = surface.cellsV;
        for (int b = 0; b <= nv; ++b) {
            for (int a = 0; a <= nu; ++a) {
                const glm::dvec3 vertex =
                    surface.origin + surface.edgeU * (double(a) / nu) + surface.edgeV * (double(b) / nv);
                model.vertices.push_back(vertex);
                model.vertexInside.push_back(vertex + 1e-4 * (centre - vertex));
                model.vertexNormal.push_back(normal);
                model.vertexSurface.push_back(s);
                model.vertexReflectance.push_back(surface.reflectance);
            }
        }
        const double area = glm::length(glm::cross(surface.edgeU, surface.edgeV)) / (double(nu) * double(nv));
        for (int b = 0; b < nv; ++b) {
            for (int a = 0; a < nu; ++a) {
                const uint32_t v0 = first + uint32_t(b * (nu + 1) + a);
                Patch patch{{v0, v0 + 1, v0 + 1 + uint32_t(nu + 1), v0 + uint32_t(nu + 1)}, s, surface.reflectance,
                            surface.emitted.empty()        ? glm::dvec3(0.0)
                            : surface.emitted.size() == 1 ? surface.emitted[0]
                                                           : surface.emitted[size_t(b) * nu + a],
                            normal, area};
                model.patches.push_back(patch);
            }
        }
    }
    return model;
}

WorldGeometry patchGeometry(const PatchModel& model) {
    WorldGeometry world;
    world.positions.reserve(model.vertices.size());
    for (const glm::dvec3& v : model.vertices) world.positions.push_back(glm::vec3(v));
    for (const Patch& p : model.patches) {
        world.triangles.push_back({p.vertex[0], p.vertex[1], p.vertex[2]});
        world.triangles.push_back({p.vertex[0], p.vertex[2], p.vertex[3]});
        for (int k = 0; k < 2; ++k) {
            world.triangleMaterial.push_back(p.surface);
            world.triangleInstance.push_back(p.surface);
        }
        world.cornerNormals.insert(world.cornerNormals.end(), 6, glm::vec3(p.normal));
    }
    return world;
}

double CameraResponse::operator()(double radiance) const {
    const double x = std::clamp(exposure * radiance, 0.0, 1.0);
    return 255.0 * portable::pow(x, 1.0 / gamma);
}

glm::dvec3 CameraResponse::operator()(const glm::dvec3& radiance) const {
    return {(*this)(radiance.x), (*this)(radiance.y), (*this)(radiance.z)};
}

double CameraResponse::inverse(double intensity) const {
    return portable::pow(std::clamp(intensity / 255.0, 0.0, 1.0), gamma) / exposure;
}

}  // namespace shadowlab
