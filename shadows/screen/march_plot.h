// The debug view of one pixel's march (screen_march.h): its samples as a table
// (`contact-shadows-march.csv`), as a plot of their depth against the depth buffer's along
// the ray (`contact-shadows-march.svg`), and drawn on the march mask
// (`contact-shadows-march-path.png`: the chosen pixel in blue, samples in front of the
// buffer green, inside a surface red).
#pragma once

#include <filesystem>
#include <vector>

#include "shadows/screen/screen_march.h"

namespace shadowlab {

// Every sample of pixel (i, j)'s march, not stopping at the first occluded one.
std::vector<MarchSample> marchSamples(const ScreenMarch& march, const GBuffer& g, int i, int j);

void writeMarchPlot(const std::filesystem::path& directory, const GBuffer& g, const std::vector<float>& mask, int i,
                    int j, const std::vector<MarchSample>& samples, float thicknessM);

}  // namespace shadowlab
