#include "frame/aov_image.h"

#include "frame/score.h"

namespace shadowlab {

ImageChannels aovImage(const Frame& frame) {
    ImageChannels aov;
    aov.width = frame.gbuffer.width, aov.height = frame.gbuffer.height;
    setRadiance(aov, frame.radiance);
    setGBuffer(aov, frame.gbuffer);
    if (frame.output == TechniqueOutput::Visibility) {
        for (const LightPass& pass : frame.passes)
            aov.set(visibilityChannel(pass.light, frame.passes.size()), pass.shadow.visibility);
    }
    // One light's stencil: a frame of several keeps V per light, within the channels
    // an EXR reader accepts (conventions.md).
    if (frame.passes.size() == 1 && !frame.shadow.stencil.empty()) aov.set(channel::stencil, frame.shadow.stencil);
    return aov;
}

}  // namespace shadowlab
