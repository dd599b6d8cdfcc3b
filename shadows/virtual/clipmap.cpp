#include "shadows/virtual/clipmap.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/camera.h"

namespace shadowlab::vsm {
namespace {

bool powerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

}  // namespace

LightFrame LightFrame::towards(const glm::dvec3& direction) {
    // The rows of the shadow maps' light rotation (light_view.cpp: lookAt from the origin
    // along -direction), so that a page's view and the frame agree to the bit.
    const glm::dvec3 z = glm::normalize(direction);
    const glm::dmat4 view = glm::lookAtRH(glm::dvec3(0.0), -z, lookAtUp(z));
    LightFrame frame;
    frame.x = {view[0][0], view[1][0], view[2][0]};
    frame.y = {view[0][1], view[1][1], view[2][1]};
    frame.z = {view[0][2], view[1][2], view[2][2]};
    return frame;
}

double ClipmapSettings::texelM(int level) const { return std::ldexp(2.0, level) / double(resolution); }

glm::dvec2 texelOf(const ClipmapSettings& settings, int level, const glm::dvec3& local) {
    const double texel = settings.texelM(level);
    return {local.x / texel, -local.y / texel};
}

LevelWindow placeLevel(const ClipmapSettings& settings, int level, const glm::dvec3& eyeLocal) {
    const glm::dvec2 eyePage = texelOf(settings, level, eyeLocal) / double(settings.pageTexels);
    const int32_t half = settings.pagesPerSide() / 2;
    // The page nearest the eye's corner is the window's centre: a sub-page move of the
    // camera leaves every level's window where it was.
    return {level, int32_t(std::lround(eyePage.x)) - half, int32_t(std::lround(eyePage.y)) - half};
}

void checkClipmapSettings(const ClipmapSettings& s) {
    const auto fail = [](const std::string& what) { throw std::invalid_argument("virtual shadow map: " + what); };
    if (!powerOfTwo(s.resolution) || s.resolution > (1 << 20))
        fail("resolution must be a power of two up to 1048576, got " + std::to_string(s.resolution));
    if (!powerOfTwo(s.pageTexels) || s.pageTexels < 16 || s.pageTexels > s.resolution / 2)
        fail("page-texels must be a power of two from 16 to half the resolution, got " + std::to_string(s.pageTexels));
    if (s.firstLevel < -kMaxLevel || s.lastLevel > kMaxLevel || s.firstLevel > s.lastLevel)
        fail("levels must satisfy -40 <= first-level <= last-level <= 40, got " + std::to_string(s.firstLevel) +
             ".." + std::to_string(s.lastLevel));
}

}  // namespace shadowlab::vsm
