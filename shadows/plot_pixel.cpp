#include "shadows/plot_pixel.h"

#include <stdexcept>

namespace shadowlab {

SettingsTable<PlotPixelSettings> plotPixelSettingsTable(const std::string& what) {
    using S = PlotPixelSettings;
    return SettingsTable<S>()
        .integer("plot-x", member(&S::x), -1, 8191,
                 "debug buffers: column of the pixel whose " + what + "; -1: the image's centre")
        .integer("plot-y", member(&S::y), -1, 8191, "debug buffers: its row; -1: the image's centre");
}

std::pair<int, int> plotPixel(const PlotPixelSettings& s, int width, int height, const std::string& technique) {
    if (s.x >= width || s.y >= height) {
        throw std::invalid_argument(technique + ": plot-x, plot-y must name a pixel of the image");
    }
    return {s.x < 0 ? width / 2 : s.x, s.y < 0 ? height / 2 : s.y};
}

}  // namespace shadowlab
