#include "shadows/fins/fin_layers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shadowlab {

LightLayers::LightLayers(std::span<const double> edgeDistance, double zNear, double zFar, int layers, int subLayers)
    : zNear_(zNear), zFar_(zFar), subLayers_(subLayers) {
    if (!(zNear > 0.0) || !(zFar > zNear) || layers < 1 || subLayers < 1) {
        throw std::invalid_argument("light layers: need 0 < zNear < zFar, layers >= 1 and sub-layers >= 1");
    }
    std::vector<int> edgesIn(subLayers, 0);
    for (double L : edgeDistance) edgesIn[subLayerOf(L)]++;
    const double total = double(edgeDistance.size());
    firstSubLayer_ = {0};
    double running = 0.0;
    for (int s = 0; s < subLayers - 1; ++s) {
        running += edgesIn[s];
        const int closed = count();
        if (closed < layers - 1 && running > 0.0 && running >= total * (closed + 1) / layers) {
            firstSubLayer_.push_back(s + 1);
        }
    }
    firstSubLayer_.push_back(subLayers);
    layerOfSubLayer_.resize(subLayers);
    for (int layer = 0; layer < count(); ++layer) {
        std::fill(layerOfSubLayer_.begin() + firstSubLayer_[layer], layerOfSubLayer_.begin() + firstSubLayer_[layer + 1],
                  layer);
    }
}

int LightLayers::subLayerOf(double L) const {
    const double s = std::floor((L - zNear_) / (zFar_ - zNear_) * subLayers_);
    return int(std::clamp(s, 0.0, double(subLayers_ - 1)));
}

int LightLayers::layerOf(double L) const { return layerOfSubLayer_[subLayerOf(L)]; }

std::vector<int> instanceLayers(const LightLayers& layers, std::span<const double> edgeDistance,
                                std::span<const uint32_t> edgeInstance, std::span<const double> fallbackDistance) {
    std::vector<std::vector<double>> distances(fallbackDistance.size());
    for (size_t e = 0; e < edgeDistance.size(); ++e) distances[edgeInstance[e]].push_back(edgeDistance[e]);
    std::vector<int> layer(fallbackDistance.size());
    for (size_t i = 0; i < layer.size(); ++i) {
        std::vector<double>& d = distances[i];
        if (d.empty()) {
            layer[i] = layers.layerOf(fallbackDistance[i]);
            continue;
        }
        std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
        layer[i] = layers.layerOf(d[d.size() / 2]);
    }
    return layer;
}

}  // namespace shadowlab
