#include "shadows/deep/curve_plot.h"

#include <algorithm>
#include <fstream>
#include <numeric>

namespace shadowlab {

std::vector<size_t> busiestTexels(const VolumetricLayers& layers, int count) {
    std::vector<size_t> texels(layers.start.size() - 1);
    std::iota(texels.begin(), texels.end(), size_t(0));
    const size_t kept = std::min(texels.size(), size_t(count));
    std::partial_sort(texels.begin(), texels.begin() + ptrdiff_t(kept), texels.end(), [&](size_t a, size_t b) {
        return layers.eventCount(a) != layers.eventCount(b) ? layers.eventCount(a) > layers.eventCount(b) : a < b;
    });
    texels.resize(kept);
    std::erase_if(texels, [&](size_t t) { return layers.eventCount(t) == 0; });
    return texels;
}

namespace {

// T (up) against window depth (right): the exact curve in black, the technique's in red.
void writeSvg(const std::filesystem::path& path, const SampledCurve& c, int x, int y) {
    constexpr double kWidth = 560, kHeight = 260, kMargin = 40;
    const double lo = c.depth.front(), hi = c.depth.back();
    const auto px = [&](double z) { return kMargin + (kWidth - 2 * kMargin) * (z - lo) / (hi - lo); };
    const auto py = [&](double t) { return kHeight - kMargin - (kHeight - 2 * kMargin) * t; };
    std::ofstream out(path);
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
        << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    out << "<text x=\"" << kMargin << "\" y=\"16\">texel (" << x << ", " << y
        << "): transmittance (0 to 1, up); black exact, red the technique's</text>\n";
    out << "<text x=\"" << kMargin << "\" y=\"" << kHeight - 12 << "\">light-space window depth: " << lo << " to " << hi
        << "</text>\n";
    out << "<rect x=\"" << kMargin << "\" y=\"" << py(1.0) << "\" width=\"" << kWidth - 2 * kMargin << "\" height=\""
        << py(0.0) - py(1.0) << "\" fill=\"none\" stroke=\"#ccc\"/>\n";
    const auto polyline = [&](const std::vector<float>& values, const char* colour) {
        out << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.5\" points=\"";
        for (size_t s = 0; s < values.size(); ++s) out << px(c.depth[s]) << ',' << py(values[s]) << ' ';
        out << "\"/>\n";
    };
    polyline(c.exact, "black");
    polyline(c.technique, "#d22");
    out << "</svg>\n";
}

}  // namespace

void writeCurvePlots(const std::filesystem::path& directory, const std::string& technique, const std::string& suffix,
                     int mapSize, const std::vector<SampledCurve>& curves) {
    std::filesystem::create_directories(directory);
    std::ofstream csv(directory / (technique + "-curves" + suffix + ".csv"));
    csv << "texel_x,texel_y,depth,exact,technique\n";
    for (const SampledCurve& c : curves) {
        const int x = int(c.texel % size_t(mapSize)), y = int(c.texel / size_t(mapSize));
        for (size_t s = 0; s < c.depth.size(); ++s) {
            csv << x << ',' << y << ',' << c.depth[s] << ',' << c.exact[s] << ',' << c.technique[s] << '\n';
        }
        const std::string name =
            technique + "-curve-" + std::to_string(x) + "-" + std::to_string(y) + suffix + ".svg";
        writeSvg(directory / name, c, x, y);
    }
}

}  // namespace shadowlab
