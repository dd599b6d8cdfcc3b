#include "compositing/sampling_detail.h"

#include <algorithm>

namespace shadowlab {

ParamSpec samplingDetailParam() {
    return choiceParam<int>("sampling-detail", "1",
                            {{"1", 1}, {"1/4", 2}, {"1/16", 4}, {"1/64", 8}, {"1/256", 16}, {"1/1024", 32}},
                            "share of the pixels the shadow buffer S is computed at");
}

Camera sampledCamera(const Camera& camera, int k) {
    Camera sampled = camera;
    sampled.width = std::max(1, (camera.width + k / 2) / k);
    sampled.height = std::max(1, (camera.height + k / 2) / k);
    return sampled;
}

}  // namespace shadowlab
