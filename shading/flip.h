// FLIP (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom, Fairchild, "FLIP: A Difference
// Evaluator for Alternating Images", HPG 2020): the difference a viewer sees when flipping
// between a test image and its reference, per pixel in [0, 1], for LDR images on a display.
// It is the colour difference (shading/flip_colour.h) raised to 1 - the feature difference
// (shading/flip_features.h), so that a changed edge or point raises a small colour error
// (sec. "Final difference map": Delta E = Delta E_c ^ (1 - Delta E_f)). Its single figure is
// the mean over the pixels (the authors' advice since the paper, over its weighted median).
// docs/conventions.md, "Figures and errors", says how shadowlab scores with it.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

// The paper's viewing condition: a 0.7 m wide 3840-pixel monitor seen from 0.7 m, 67 pixels
// per degree of visual angle.
inline constexpr float kFlipPixelsPerDegree = 67.0f;

struct FlipSettings {
    float pixelsPerDegree = kFlipPixelsPerDegree;
};

struct FlipErrorMap {
    int width = 0, height = 0;
    std::vector<float> error;   // row-major, row 0 at the top, each in [0, 1]
};

// Both images display-referred linear RGB in [0, 1] (tone mapped, before the sRGB encoding),
// width x height, row-major. Rows in parallel: the same bits for any thread count. Throws
// std::invalid_argument if a size differs or pixelsPerDegree is not positive.
FlipErrorMap flipErrorMap(const std::vector<glm::vec3>& reference, const std::vector<glm::vec3>& test, int width,
                          int height, const FlipSettings& settings = {});

// The mean of the map over every pixel, or over the pixels where mask is nonzero (a mask of the
// map's size; 0 if it selects none). Summed in double, row by row, rows in order.
double flipMean(const FlipErrorMap& map);
double flipMean(const FlipErrorMap& map, const std::vector<float>& mask);

// RGB bytes (row 0 at the top) for writePng(): the error as grey, sRGB-encoded, for debugging.
std::vector<uint8_t> flipErrorImage(const FlipErrorMap& map);

}  // namespace shadowlab
