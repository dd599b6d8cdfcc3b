#include "shadows/screen/screen_march.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "scenes/camera.h"
#include "shading/lights.h"

namespace shadowlab {

ScreenMarch::ScreenMarch(const GBuffer& g, const Camera& camera, const Light& pointLight, const MarchSettings& settings)
    : g_(g), clipFromWorld_(clipFromWorld(camera)), eye_(camera.eye),
      forward_(glm::normalize(camera.target - camera.eye)), zNear_(camera.zNear),
      pixelFootprint_(2.0f / (clipFromView(camera)[1][1] * float(camera.height))), light_(pointLight),
      settings_(settings) {}

bool ScreenMarch::toPixel(const glm::vec4& clip, float depth, glm::vec2& pixel) const {
    if (!(depth >= zNear_)) return false;
    pixel = glm::vec2((clip.x / clip.w * 0.5f + 0.5f) * float(g_.width),
                      (0.5f - clip.y / clip.w * 0.5f) * float(g_.height));
    return pixel.x >= 0.0f && pixel.y >= 0.0f && pixel.x < float(g_.width) && pixel.y < float(g_.height);
}

ScreenMarch::Mask ScreenMarch::mask() const {
    Mask out{std::vector<float>(g_.pixelCount(), 1.0f), std::vector<uint8_t>(g_.pixelCount(), uint8_t(MarchEnd::Lit))};
    const LightReach reaches(light_);
    tbb::parallel_for(tbb::blocked_range<int>(0, g_.height), [&](const tbb::blocked_range<int>& rows) {
        for (int j = rows.begin(); j < rows.end(); ++j) {
            for (int i = 0; i < g_.width; ++i) {
                const size_t k = g_.index(i, j);
                if (!g_.hit[k] || !reaches(g_.position[k], g_.normal[k])) continue;
                const MarchEnd end = march(k, [](const MarchSample& s) { return s.occluded; });
                out.end[k] = uint8_t(end);
                if (end == MarchEnd::Occluded) out.visibility[k] = 0.0f;
            }
        }
    });
    return out;
}

}  // namespace shadowlab
