#include "differential/differential_reference.h"

#include <tbb/parallel_for.h>

#include "differential/patch_radiance.h"
#include "scenes/bounds.h"
#include "scenes/float_range.h"
#include "shadows/camera_pass.h"

namespace shadowlab {
namespace {

// Whether some segment from x to a point of the patch (within its bounding sphere) may pass
// through the object's sphere: a point at t along x -> q lies within t r_patch of the same
// point along x -> c, so the segment x -> c must pass within r_object + r_patch.
bool mayBlock(const Sphere& object, const Sphere& patch, const glm::dvec3& x) {
    const glm::dvec3 d = patch.centre - x;
    const double t = std::clamp(glm::dot(object.centre - x, d) / glm::dot(d, d), 0.0, 1.0);
    const double reach = object.radius + patch.radius;
    const glm::dvec3 gap = x + t * d - object.centre;
    return glm::dot(gap, gap) <= reach * reach;
}

}  // namespace

std::vector<glm::vec3> differentialReference(const DifferentialModel& m, const PreparedObject& object,
                                             std::span<const glm::mat4> placements, const PatchSampling& sampling) {
    requireFinitePlacements(placements, "differential reference");
    const WorldGeometry whole = placed(object.levels.whole, placements);
    const ReferenceVisibility objectRays(whole, nullptr);   // the object's mesh: opaque
    const Aabb box = boundsOf(whole);
    const Sphere objectSphere = boundingSphere(box);
    const std::vector<uint32_t> radiant = radiantPatches(m.model, m.radiance);
    std::vector<Sphere> patchSpheres;
    for (const uint32_t j : radiant) patchSpheres.push_back(boundingSphere(patchBounds(m.model, j)));
    // The camera's view with the object: its pixels, and which are the model's.
    const uint32_t modelTriangles = uint32_t(m.geometry.triangles.size());
    const GBuffer g = renderGBuffer(withObject(m, whole), m.camera, raster::SimdLevel::Scalar);
    std::vector<glm::vec3> image = m.background;
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            const glm::dvec3 x(g.position[k]);
            if (g.triangle[k] >= modelTriangles) {
                // On the object: I_obj, every patch with the model and the object in the way;
                // the cosine at the smooth shading normal, the rays off the triangle's plane.
                const glm::vec3 N = g.normal[k];
                const auto seen = [&](const glm::dvec3& q) {
                    return objectRays.pointVisible(g.position[k], N, q) &&
                           m.modelRays->pointVisible(g.position[k], N, q);
                };
                const glm::dvec3 albedo(object.levels.whole.materials[g.material[k]].albedo);
                image[k] = glm::vec3(albedo * gatheredRadiance(m.model, m.radiance, radiant, x,
                                                               glm::dvec3(g.shadingNormal[k]), sampling, k, seen));
                continue;
            }
            const Patch& patch = m.model.patches[g.triangle[k] / 2];
            if (patch.reflectance == glm::dvec3(0.0)) continue;
            const glm::vec3 N(patch.normal);
            // Samples the model lets through and the object blocks: I_noobj - I_obj.
            const auto blockedByObject = [&](const glm::dvec3& q) {
                return !objectRays.pointVisible(g.position[k], N, q) && m.modelRays->pointVisible(g.position[k], N, q);
            };
            glm::dvec3 lost(0.0);
            for (size_t r = 0; r < radiant.size(); ++r) {
                if (!mayBlock(objectSphere, patchSpheres[r], x)) continue;
                lost += patchTransfer(m.model, m.radiance[radiant[r]], radiant[r], x, patch.normal, sampling, k,
                                      blockedByObject);
            }
            image[k] = glm::max(image[k] - glm::vec3(patch.reflectance * lost), glm::vec3(0.0f));
        }
    });
    return image;
}

}  // namespace shadowlab
