#include "shading/motion_vectors.h"

#include <limits>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

#include "scenes/camera.h"
#include "shading/gbuffer_build.h"

namespace shadowlab {
namespace {

// How one instance moved from the frame before to this one, as a map from where its points
// are now to where they were.
struct InstanceMove {
    bool moved = false;
    glm::dmat4 previousFromCurrent{1.0};   // M' M^-1
    glm::dmat3 normalPreviousFromCurrent{1.0};   // its inverse transpose, for normals
};

std::vector<InstanceMove> instanceMoves(const Scene& scene, const PreviousView& previous) {
    if (previous.worldFromObject.size() != scene.instances.size())
        throw std::invalid_argument("motion vectors: the frame before had " +
                                    std::to_string(previous.worldFromObject.size()) + " instances, this one " +
                                    std::to_string(scene.instances.size()) + ": another scene");
    std::vector<InstanceMove> moves(scene.instances.size());
    for (size_t k = 0; k < moves.size(); ++k) {
        const glm::mat4& now = scene.instances[k].worldFromObject;
        const glm::mat4& then = previous.worldFromObject[k];
        if (now == then) continue;   // exactly P: no round trip through an inverse
        InstanceMove& m = moves[k];
        m.moved = true;
        m.previousFromCurrent = glm::dmat4(then) * glm::inverse(glm::dmat4(now));
        m.normalPreviousFromCurrent = glm::transpose(glm::inverse(glm::dmat3(m.previousFromCurrent)));
    }
    return moves;
}

}  // namespace

PreviousView keepView(const GBuffer& g, const Scene& scene) {
    requireConsistent(g, "keepView");
    if (g.width != scene.camera.width || g.height != scene.camera.height)
        throw std::invalid_argument("keepView: the G-buffer is not the camera's size");
    PreviousView view{scene.camera, {}, g.hit, g.position, g.normal};
    for (const MeshInstance& instance : scene.instances) view.worldFromObject.push_back(instance.worldFromObject);
    return view;
}

SurfaceMotion surfaceMotion(const GBuffer& g, const WorldGeometry& world, const Scene& scene,
                            const PreviousView& previous) {
    requireConsistent(g, "surfaceMotion");
    const std::vector<InstanceMove> moves = instanceMoves(scene, previous);
    const glm::dmat4 clipFromWorldBefore = clipFromWorldD(previous.camera);
    // A point that did not move, under a camera that did not, is still on its pixel centre's
    // ray: its offset is 0 exactly, where projecting the G-buffer's rounded P would give
    // a few millionths of a pixel.
    const bool stillCamera = previous.camera == scene.camera;
    const double width = previous.camera.width, height = previous.camera.height;
    const size_t n = g.pixelCount();
    SurfaceMotion m{std::vector<glm::vec2>(n, glm::vec2(0.0f)), std::vector<glm::vec3>(n, glm::vec3(0.0f)),
                    std::vector<glm::vec3>(n, glm::vec3(0.0f))};
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            const uint32_t t = g.triangle[k];
            if (t >= world.triangleInstance.size())
                throw std::invalid_argument("surfaceMotion: pixel triangle " + std::to_string(t) + " is not in the world");
            const InstanceMove& move = moves[world.triangleInstance[t]];
            glm::dvec3 p(g.position[k]);
            glm::vec3 normal = g.normal[k];
            if (move.moved) {
                p = glm::dvec3(move.previousFromCurrent * glm::dvec4(p, 1.0));
                normal = glm::vec3(glm::normalize(move.normalPreviousFromCurrent * glm::dvec3(normal)));
            }
            m.previousPosition[k] = glm::vec3(p);
            m.previousNormal[k] = normal;
            if (stillCamera && !move.moved) continue;   // offset 0
            // Behind the previous camera a point had no place in its image.
            const glm::dvec4 clip = clipFromWorldBefore * glm::dvec4(p, 1.0);
            if (!(clip.w > 0.0)) {
                m.pixelOffset[k] = glm::vec2(std::numeric_limits<float>::infinity());
                continue;
            }
            const double x = (clip.x / clip.w + 1.0) * 0.5 * width;   // camera.cpp's PixelRays, inverted
            const double y = (1.0 - clip.y / clip.w) * 0.5 * height;
            m.pixelOffset[k] = glm::vec2(float(x - (i + 0.5)), float(y - (j + 0.5)));
        }
    });
    return m;
}

}  // namespace shadowlab
