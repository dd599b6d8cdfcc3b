#include "shadows/screen/march_plot.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "shadows/debug_buffers.h"

namespace shadowlab {
namespace {

void writeCsv(const std::filesystem::path& path, const std::vector<MarchSample>& samples) {
    std::ofstream out(path);
    out << "step,distance_m,pixel_x,pixel_y,sample_depth_m,buffer_depth_m,occluded\n";
    for (size_t n = 0; n < samples.size(); ++n) {
        const MarchSample& s = samples[n];
        out << n + 1 << ',' << s.distanceM << ',' << s.pixel.x << ',' << s.pixel.y << ',' << s.sampleDepth << ',';
        if (std::isfinite(s.bufferDepth)) out << s.bufferDepth;
        else out << "none";
        out << ',' << int(s.occluded) << '\n';
    }
}

// Depth (down the page, as the camera looks into it) against the distance along the ray:
// the samples joined by a line, the buffer's surface under each sample as a tick, and the
// band of the depth thickness behind it, where a sample counts as inside.
void writeSvg(const std::filesystem::path& path, const std::vector<MarchSample>& samples, float thicknessM) {
    constexpr double kWidth = 560, kHeight = 300, kMargin = 40;
    double lo = samples.front().sampleDepth, hi = lo;
    for (const MarchSample& s : samples) {
        lo = std::min(lo, double(s.sampleDepth)), hi = std::max(hi, double(s.sampleDepth));
        if (std::isfinite(s.bufferDepth)) hi = std::max(hi, double(s.bufferDepth) + thicknessM);
    }
    const double reach = samples.back().distanceM, span = std::max(hi - lo, 1e-6);
    const auto x = [&](double d) { return kMargin + (kWidth - 2 * kMargin) * d / reach; };
    const auto y = [&](double depth) { return kMargin + (kHeight - 2 * kMargin) * (depth - lo) / span; };
    std::ofstream out(path);
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
        << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    out << "<text x=\"" << kMargin << "\" y=\"16\">view depth, m (down): " << lo << " to " << hi << "</text>\n";
    out << "<text x=\"" << kMargin << "\" y=\"" << kHeight - 12 << "\">distance along the ray to the light, m: 0 to "
        << reach << "; green: in front, red: inside (bars: thickness)</text>\n";
    for (const MarchSample& s : samples) {
        if (!std::isfinite(s.bufferDepth)) continue;
        out << "<rect x=\"" << x(s.distanceM) - 3 << "\" y=\"" << y(s.bufferDepth) << "\" width=\"6\" height=\""
            << y(s.bufferDepth + thicknessM) - y(s.bufferDepth) << "\" fill=\"#ddd\"/>\n";
        out << "<line x1=\"" << x(s.distanceM) - 5 << "\" x2=\"" << x(s.distanceM) + 5 << "\" y1=\"" << y(s.bufferDepth)
            << "\" y2=\"" << y(s.bufferDepth) << "\" stroke=\"black\"/>\n";
    }
    out << "<polyline fill=\"none\" stroke=\"#888\" points=\"";
    for (const MarchSample& s : samples) out << x(s.distanceM) << ',' << y(s.sampleDepth) << ' ';
    out << "\"/>\n";
    for (const MarchSample& s : samples) {
        out << "<circle cx=\"" << x(s.distanceM) << "\" cy=\"" << y(s.sampleDepth) << "\" r=\"3\" fill=\""
            << (s.occluded ? "red" : "green") << "\"/>\n";
    }
    out << "</svg>\n";
}

void writePath(const std::filesystem::path& directory, const GBuffer& g, const std::vector<float>& mask, int i, int j,
               const std::vector<MarchSample>& samples) {
    // Surfaces grey by their normal, so that faces stand apart; darker where the march shadows.
    const glm::vec3 key = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f));
    std::vector<uint8_t> rgb(g.pixelCount() * 3);
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        const float facing = std::abs(glm::dot(g.normal[k], key));
        const uint8_t grey = uint8_t(g.hit[k] ? (mask[k] > 0.0f ? 130.0f : 40.0f) + 60.0f * facing : 0.0f);
        rgb[3 * k] = rgb[3 * k + 1] = rgb[3 * k + 2] = grey;
    }
    const auto paint = [&](int x, int y, uint8_t r, uint8_t gr, uint8_t b) {
        if (x < 0 || y < 0 || x >= g.width || y >= g.height) return;
        const size_t k = g.index(x, y);
        rgb[3 * k] = r, rgb[3 * k + 1] = gr, rgb[3 * k + 2] = b;
    };
    for (const MarchSample& s : samples) {
        const int x = int(s.pixel.x), y = int(s.pixel.y);
        for (int d = 0; d < 9; ++d) paint(x + d % 3 - 1, y + d / 3 - 1, s.occluded ? 255 : 0, s.occluded ? 0 : 200, 0);
    }
    for (int d = -2; d <= 2; ++d) paint(i + d, j, 40, 90, 255), paint(i, j + d, 40, 90, 255);
    DebugBuffers(directory, "contact-shadows").writePicture("march-path", g.width, g.height, rgb);
}

}  // namespace

std::vector<MarchSample> marchSamples(const ScreenMarch& march, const GBuffer& g, int i, int j) {
    return march.samples(g.index(i, j));
}

void writeMarchPlot(const std::filesystem::path& directory, const GBuffer& g, const std::vector<float>& mask, int i,
                    int j, const std::vector<MarchSample>& samples, float thicknessM) {
    writePath(directory, g, mask, i, j, samples);
    if (samples.empty()) return;   // the first step already left the screen
    writeCsv(directory / "contact-shadows-march.csv", samples);
    writeSvg(directory / "contact-shadows-march.svg", samples, thicknessM);
}

}  // namespace shadowlab
