// `plot-x`, `plot-y`: the pixel whose work a technique's debug view draws, rows a technique
// includes in its settings table (backprojection, contact-shadows).
#pragma once

#include <string>
#include <utility>

#include "shadows/settings_table.h"

namespace shadowlab {

struct PlotPixelSettings {
    int x = -1;   // -1: the image's centre
    int y = -1;
};

// Its rows; `what` says what is drawn ("march is plotted").
SettingsTable<PlotPixelSettings> plotPixelSettingsTable(const std::string& what);

// The pixel in a width x height image; std::invalid_argument naming the technique where it
// lies outside.
std::pair<int, int> plotPixel(const PlotPixelSettings& settings, int width, int height, const std::string& technique);

}  // namespace shadowlab
