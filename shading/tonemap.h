// From linear radiance to 8-bit sRGB pixels for people to look at (conventions.md: "8-bit
// PNG output is sRGB-encoded after tone mapping; it is for people, the EXR is for checks").
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

enum class ToneOperator {
    Clamp,     // each channel clipped to [0, 1]
    Reinhard,  // luminance Y -> Y / (1 + Y), colour scaled by the same ratio
};

struct ToneMapOptions {
    float exposureStops = 0.0f;  // radiance is multiplied by 2^exposureStops first
    ToneOperator op = ToneOperator::Reinhard;
};

// Exposure and operator: a display-referred linear colour, each channel in [0, 1].
glm::vec3 toneMap(const glm::vec3& radiance, const ToneMapOptions& options);

// The sRGB opto-electronic transfer function of IEC 61966-2-1 for a linear value in
// [0, 1]: 12.92 c for c <= 0.0031308, else 1.055 c^(1/2.4) - 0.055.
double srgbEncode(double linear);

// Its inverse (IEC 61966-2-1, section 5.2), for an encoded value in [0, 1]: c / 12.92 for
// c <= 0.04045, else ((c + 0.055) / 1.055)^2.4.
double srgbDecode(double encoded);
// 8-bit sRGB codes, R G B interleaved, to linear colours in [0, 1], one per pixel (a PNG as
// the display shows it, for FLIP).
std::vector<glm::vec3> linearFromSrgb8(const std::vector<uint8_t>& rgb);

// Linear [0, 1] -> sRGB-encoded 8-bit code, round to nearest. Values outside [0, 1] are
// clamped first; NaN maps to 0.
uint8_t toSrgb8(float linear);

// Whole image: tone map, encode, interleave as R G B bytes, row 0 at the top.
std::vector<uint8_t> toSrgb8Image(const std::vector<glm::vec3>& radiance,
                                  const ToneMapOptions& options);

}  // namespace shadowlab
