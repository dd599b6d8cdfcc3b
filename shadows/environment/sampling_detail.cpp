#include "shadows/environment/sampling_detail.h"

#include <algorithm>

namespace shadowlab {

std::vector<Choice<int>> samplingDetailChoices() {
    return {{"1", 1}, {"1/4", 2}, {"1/16", 4}, {"1/64", 8}, {"1/256", 16}, {"1/1024", 32}};
}

Camera sampledCamera(const Camera& camera, int k) {
    Camera sampled = camera;
    sampled.width = std::max(1, (camera.width + k / 2) / k);
    sampled.height = std::max(1, (camera.height + k / 2) / k);
    return sampled;
}

}  // namespace shadowlab
