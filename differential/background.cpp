#include "differential/background.h"

#include <tbb/parallel_for.h>

#include "differential/patch_radiance.h"
#include "shadows/camera_pass.h"

namespace shadowlab {
namespace {

// (u, v) with P = v0 + u (v1 - v0) + v (v3 - v0), by the normal equations (P lies in the
// cell's plane up to rounding).
glm::dvec2 cellCoordinates(const PatchModel& model, uint32_t p, const glm::dvec3& P) {
    const std::array<glm::dvec3, 4> c = model.corners(p);
    const glm::dvec3 e1 = c[1] - c[0], e2 = c[3] - c[0], d = P - c[0];
    const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), e = glm::dot(e2, e2);
    const double r1 = glm::dot(e1, d), r2 = glm::dot(e2, d), det = a * e - b * b;
    return {glm::clamp((e * r1 - b * r2) / det, 0.0, 1.0), glm::clamp((a * r2 - b * r1) / det, 0.0, 1.0)};
}

}  // namespace

PixelPatches pixelPatches(const PatchModel& model, const WorldGeometry& geometry, const Camera& camera,
                          raster::SimdLevel simd) {
    PixelPatches pixels{renderGBuffer(geometry, camera, simd), {}, {}};
    const size_t count = pixels.gbuffer.pixelCount();
    pixels.patch.assign(count, kNoPatch);
    pixels.uv.assign(count, glm::vec2(0.0f));
    for (size_t k = 0; k < count; ++k) {
        if (!pixels.gbuffer.hit[k]) continue;
        const uint32_t p = pixels.gbuffer.triangle[k] / 2;
        pixels.patch[k] = p;
        pixels.uv[k] = glm::vec2(cellCoordinates(model, p, glm::dvec3(pixels.gbuffer.position[k])));
    }
    return pixels;
}

std::vector<glm::vec3> renderBackground(const PatchModel& model, const std::vector<glm::dvec3>& radiance,
                                        const PixelPatches& pixels, const ReferenceVisibility& modelRays,
                                        const PatchSampling& sampling) {
    const std::vector<uint32_t> sources = radiantPatches(model, radiance);
    const GBuffer& g = pixels.gbuffer;
    std::vector<glm::vec3> image(g.pixelCount(), glm::vec3(0.0f));
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (pixels.patch[k] == kNoPatch) continue;
            const Patch& patch = model.patches[pixels.patch[k]];
            const glm::dvec3 x(g.position[k]);
            if (glm::dot(glm::dvec3(g.normal[k]), patch.normal) <= 0.0) continue;   // its back
            const auto seen = [&](const glm::dvec3& q) {
                return modelRays.pointVisible(g.position[k], glm::vec3(patch.normal), q);
            };
            image[k] = glm::vec3(patch.emitted +
                                 patch.reflectance * gatheredRadiance(model, radiance, sources, x, patch.normal,
                                                                      sampling, k, seen));
        }
    });
    return image;
}

}  // namespace shadowlab
