#include "shading/temporal_stability.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace shadowlab {

FlickerFigures flickerFigures(const ImageChannels& previousReference, const ImageChannels& reference,
                              const ImageChannels& previousTest, const ImageChannels& test, const std::string& channel,
                              float tolerance) {
    for (const ImageChannels* image : {&previousReference, &previousTest, &test}) {
        if (image->width != reference.width || image->height != reference.height)
            throw std::invalid_argument("flicker: the four images must have one size");
    }
    const std::vector<float>& hit0 = previousReference.at("hit");
    const std::vector<float>& hit1 = reference.at("hit");
    const std::vector<float>& ref0 = previousReference.at(channel);
    const std::vector<float>& ref1 = reference.at(channel);
    const std::vector<float>& test0 = previousTest.at(channel);
    const std::vector<float>& test1 = test.at(channel);
    FlickerFigures figures;
    std::vector<float> change;
    for (size_t p = 0; p < reference.pixelCount(); ++p) {
        if (hit0[p] == 0.0f || hit1[p] == 0.0f) continue;
        ++figures.pixels;
        if (!(std::abs(ref1[p] - ref0[p]) <= tolerance)) continue;
        change.push_back(std::abs(test1[p] - test0[p]));
    }
    figures.stablePixels = change.size();
    if (change.empty()) return figures;
    if (std::ranges::any_of(change, [](float d) { return std::isnan(d); })) {
        figures.mean = figures.p99 = std::numeric_limits<double>::quiet_NaN();
        return figures;
    }
    double sum = 0.0;
    for (float d : change) sum += d;
    figures.mean = sum / double(change.size());
    const size_t rank = (change.size() * 99 + 99) / 100;   // ceil(0.99 n), at least 1
    std::ranges::nth_element(change, change.begin() + ptrdiff_t(rank - 1));
    figures.p99 = change[rank - 1];
    return figures;
}

}  // namespace shadowlab
