#include "shading/flip.h"

#include <stdexcept>

#include "raster/portable_math.h"
#include "shading/flip_colour.h"
#include "shading/flip_features.h"
#include "shading/tonemap.h"

namespace shadowlab {
namespace {

// The feature pipeline's input: Yy of the unfiltered opponent colour, made a luminance in
// [0, 1] again, (Yy + 16) / 116 = Y / Y_n (the paper's erratum: 116, not 100).
flip::Plane achromatic(const std::vector<glm::vec3>& rgb, int width, int height) {
    flip::Plane plane(width, height);
    flip::forEachPixel(width, height, [&](size_t p) {
        plane.values[p] = (flip::linearRgbToYyCxCz(rgb[p]).x + 16.0f) / 116.0f;
    });
    return plane;
}

// Sums f(p) over one row's pixels into a double, rows in parallel, then the rows in order.
template <class F>
double sumByRows(int width, int height, const F& f) {
    std::vector<double> rowSums(size_t(height), 0.0);
    tbb::parallel_for(0, height, [&](int y) {
        double sum = 0.0;
        for (size_t p = size_t(y) * size_t(width); p < size_t(y + 1) * size_t(width); ++p) sum += f(p);
        rowSums[size_t(y)] = sum;
    });
    double total = 0.0;
    for (double s : rowSums) total += s;
    return total;
}

}  // namespace

FlipErrorMap flipErrorMap(const std::vector<glm::vec3>& reference, const std::vector<glm::vec3>& test, int width,
                          int height, const FlipSettings& settings) {
    const flip::Plane colour = flip::colourDifference(reference, test, width, height, settings.pixelsPerDegree);
    const flip::Plane features = flip::featureDifference(achromatic(reference, width, height),
                                                         achromatic(test, width, height), settings.pixelsPerDegree);
    FlipErrorMap map{width, height, std::vector<float>(colour.values.size())};
    flip::forEachPixel(width, height, [&](size_t p) {
        map.error[p] = portable::powFloat(colour.values[p], 1.0f - features.values[p]);
    });
    return map;
}

double flipMean(const FlipErrorMap& map) {
    if (map.error.empty()) return 0.0;
    return sumByRows(map.width, map.height, [&](size_t p) { return double(map.error[p]); }) / double(map.error.size());
}

double flipMean(const FlipErrorMap& map, const std::vector<float>& mask) {
    if (mask.size() != map.error.size()) throw std::invalid_argument("FLIP mean: the mask and the map differ in size");
    const double count = sumByRows(map.width, map.height, [&](size_t p) { return mask[p] != 0.0f ? 1.0 : 0.0; });
    const double sum =
        sumByRows(map.width, map.height, [&](size_t p) { return mask[p] != 0.0f ? double(map.error[p]) : 0.0; });
    return count == 0.0 ? 0.0 : sum / count;
}

std::vector<uint8_t> flipErrorImage(const FlipErrorMap& map) {
    std::vector<uint8_t> rgb(3 * map.error.size());
    for (size_t p = 0; p < map.error.size(); ++p) rgb[3 * p] = rgb[3 * p + 1] = rgb[3 * p + 2] = toSrgb8(map.error[p]);
    return rgb;
}

}  // namespace shadowlab
