// A one-row image of hit and V channels, for tests of the error figures and maps.
#pragma once

#include <utility>
#include <vector>

#include "shading/image_io.h"

namespace shadowlab::test {

inline ImageChannels visibilityRow(std::vector<float> hit, std::vector<float> v) {
    ImageChannels image;
    image.width = int(hit.size());
    image.height = 1;
    image.set(channel::hit, std::move(hit));
    image.set(channel::V, std::move(v));
    return image;
}

}  // namespace shadowlab::test
