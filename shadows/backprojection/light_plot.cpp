#include "shadows/backprojection/light_plot.h"

#include <fstream>

namespace shadowlab {

void writeLightPlot(const std::filesystem::path& path, const LightGrid& grid, bool disk, const LightBitmask& hidden,
                    const std::vector<glm::vec2>& patches, int level) {
    constexpr double kSize = 512.0, kMargin = 16.0;
    const auto x = [&](double a) { return kMargin + (a + 1.0) * 0.5 * (kSize - 2.0 * kMargin); };
    const auto y = [&](double b) { return kMargin + (1.0 - b) * 0.5 * (kSize - 2.0 * kMargin); };   // b up
    std::ofstream out(path);
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kSize << "\" height=\"" << kSize + 24 << "\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    const int n = grid.perAxis();
    const double cell = (kSize - 2.0 * kMargin) / n;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            if (!(grid.onLight().rows[size_t(j)] >> i & 1u)) continue;
            const bool dark = hidden.rows[size_t(j)] >> i & 1u;
            out << "<rect x=\"" << x(grid.centre(i)) - 0.5 * cell << "\" y=\"" << y(grid.centre(j)) - 0.5 * cell
                << "\" width=\"" << cell << "\" height=\"" << cell << "\" fill=\"" << (dark ? "#404040" : "#ffe680")
                << "\" stroke=\"#bbbbbb\" stroke-width=\"0.5\"/>\n";
        }
    }
    if (disk) {
        out << "<circle cx=\"" << x(0) << "\" cy=\"" << y(0) << "\" r=\"" << x(1) - x(0);
    } else {
        out << "<rect x=\"" << x(-1) << "\" y=\"" << y(1) << "\" width=\"" << x(1) - x(-1) << "\" height=\""
            << y(-1) - y(1);
    }
    out << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (size_t p = 0; p + 3 < patches.size(); p += 4) {
        out << "<polygon fill=\"none\" stroke=\"#d03030\" stroke-width=\"0.8\" points=\"";
        for (size_t c = 0; c < 4; ++c) out << x(patches[p + c].x) << "," << y(patches[p + c].y) << " ";
        out << "\"/>\n";
    }
    out << "<text x=\"" << kMargin << "\" y=\"" << kSize + 16 << "\" font-family=\"sans-serif\" font-size=\"13\">"
        << patches.size() / 4 << " patches at level " << level << " (red) over " << grid.sampleCount()
        << " light samples: hidden dark, visible yellow</text>\n</svg>\n";
}

}  // namespace shadowlab
