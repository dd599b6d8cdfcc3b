#include "shading/pixel_sequence.h"

#include <cmath>

#include "shading/light_sampling.h"

namespace shadowlab {

double interleavedGradientNoise(double x, double y) {
    const double inner = 0.06711056 * x + 0.00583715 * y;
    const double outer = 52.9829189 * (inner - std::floor(inner));
    // A multiple of 2^-32, as sobol02's points are, so that their shifted sum is exact.
    return std::floor((outer - std::floor(outer)) * 0x1p32) * 0x1p-32;
}

glm::dvec2 pixelShift(const PixelSequence& sequence, int x, int y, uint64_t pixel) {
    Pcg32 hash(sequence.seed, pixel);
    return {interleavedGradientNoise(double(x), double(y)), hash.nextDouble()};
}

void pixelSamples(const PixelSequence& sequence, int x, int y, uint64_t pixel, std::vector<glm::dvec2>& out) {
    const glm::dvec2 shift = pixelShift(sequence, x, y, pixel);
    const uint32_t first = sequence.frame * uint32_t(sequence.count);   // wraps after 2^32 points: still the sequence's
    out.resize(size_t(sequence.count));
    for (uint32_t s = 0; s < uint32_t(sequence.count); ++s) out[s] = shiftedSobol02(first + s, shift);
}

}  // namespace shadowlab
