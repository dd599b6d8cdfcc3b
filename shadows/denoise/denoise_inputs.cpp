#include "shadows/denoise/denoise_inputs.h"

#include <stdexcept>

namespace shadowlab {

void checkDenoiseInputs(const DenoiseInputs& in, bool needsDistance) {
    const size_t n = in.gbuffer.pixelCount();
    if (in.visibility.size() != n) throw std::invalid_argument("denoiser: V is not of the G-buffer's size");
    if (needsDistance && in.occluderDistance.size() != n)
        throw std::invalid_argument("denoiser: the occluder distances are not of the G-buffer's size");
}

}  // namespace shadowlab
