// Tone mapping and sRGB encoding.
//
// Reinhard's global operator (Reinhard, Stark, Shirley, Ferwerda, "Photographic Tone
// Reproduction for Digital Images", SIGGRAPH 2002, eq. 3 without the white point) is
// applied to luminance only, so hue is kept: Y' = Y / (1 + Y) and every channel is scaled
// by Y'/Y. Saturated colours can still exceed 1 in one channel; the final clamp handles it.
// Luminance uses the Rec. 709 / sRGB primaries' weights (ITU-R BT.709, item 3.2).
#include "shading/tonemap.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "raster/portable_math.h"
#include "shading/luminance.h"

namespace shadowlab {
namespace {

glm::vec3 reinhard(const glm::vec3& c) {
    const float Y = luminance(c);
    return Y > 0.0f ? c * (1.0f / (1.0f + Y)) : glm::vec3(0.0f);
}

}  // namespace

glm::vec3 toneMap(const glm::vec3& radiance, const ToneMapOptions& options) {
    // 2^0 is exactly 1: the default exposure skips the exponential, which costs more than the
    // rest of the operator (FLIP tone maps every pixel of two images per scored frame).
    const float scale = options.exposureStops == 0.0f ? 1.0f : float(portable::exp2(options.exposureStops));
    const glm::vec3 exposed = radiance * scale;
    const glm::vec3 mapped = options.op == ToneOperator::Reinhard ? reinhard(exposed) : exposed;
    return glm::clamp(mapped, 0.0f, 1.0f);
}

double srgbEncode(double linear) {
    // IEC 61966-2-1:1999, section 5.2: the linear segment below 0.0031308 avoids the
    // infinite slope of the power curve at 0; the two pieces meet at 0.04045.
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * portable::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgbDecode(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : portable::pow((encoded + 0.055) / 1.055, 2.4);
}

std::vector<glm::vec3> linearFromSrgb8(const std::vector<uint8_t>& rgb) {
    std::array<float, 256> linear;
    for (size_t code = 0; code < linear.size(); ++code) linear[code] = float(srgbDecode(double(code) / 255.0));
    std::vector<glm::vec3> colours(rgb.size() / 3);
    for (size_t p = 0; p < colours.size(); ++p)
        colours[p] = {linear[rgb[3 * p]], linear[rgb[3 * p + 1]], linear[rgb[3 * p + 2]]};
    return colours;
}

uint8_t toSrgb8(float linear) {
    if (!(linear > 0.0f)) {
        return 0;  // also catches NaN
    }
    const double encoded = srgbEncode(std::min(double(linear), 1.0));
    return uint8_t(std::floor(encoded * 255.0 + 0.5));
}

std::vector<uint8_t> toSrgb8Image(const std::vector<glm::vec3>& radiance,
                                  const ToneMapOptions& options) {
    std::vector<uint8_t> bytes(radiance.size() * 3);
    for (size_t p = 0; p < radiance.size(); ++p) {
        const glm::vec3 display = toneMap(radiance[p], options);
        for (int c = 0; c < 3; ++c) {
            bytes[3 * p + size_t(c)] = toSrgb8(display[c]);
        }
    }
    return bytes;
}

}  // namespace shadowlab
