// Motion vectors: where each pixel's surface point was in the frame before (docs/temporal.md).
// A temporal technique reads its own result of the frame before at that place (shadows/
// temporal/reprojection.h), as an engine's TAA and denoisers read theirs; the frame pipeline
// keeps the previous frame's view (PreviousView) and fills GBuffer::motion from it
// (frame/render.h).
//
// The point P a pixel sees lies on a triangle of instance k; carried back with its instance
// it was at P' = M'_k M_k^-1 P (M_k the instance's worldFromObject now, M'_k then), exactly P
// for an instance that did not move. The previous camera projects P' to the pixel position
// it had, in double; its normal is N turned by the same move (the inverse transpose of
// M'_k M_k^-1's linear part). Nothing is rasterised: a point hidden in the frame before gets
// a motion vector all the same, which is why a reader tests the previous frame's surface at
// the place it points to (disocclusion).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

// What a sequence of frames keeps of its frame before for the next one's reprojection.
struct PreviousView {
    Camera camera;
    std::vector<glm::mat4> worldFromObject;   // each instance's, in the order of Scene::instances
    // The surfaces it saw, as the G-buffer had them: hit, P and the geometric N (facing that
    // camera), per pixel of camera.width x camera.height.
    std::vector<uint8_t> hit;
    std::vector<glm::vec3> position, normal;

    size_t index(int i, int j) const { return size_t(j) * size_t(camera.width) + size_t(i); }
};

// The view a frame leaves for the next: its camera, its instances' transforms and its
// G-buffer's surfaces. Throws std::invalid_argument if the G-buffer is not the camera's size.
PreviousView keepView(const GBuffer& gbuffer, const Scene& scene);

// SurfaceMotion (gbuffer.h) of every hit pixel of `gbuffer`, a view of `scene` over `world`,
// against the frame before. Throws std::invalid_argument if the previous view has another
// number of instances (another scene), or a pixel's triangle is not in `world`.
SurfaceMotion surfaceMotion(const GBuffer& gbuffer, const WorldGeometry& world, const Scene& scene,
                            const PreviousView& previous);

}  // namespace shadowlab
