#include "shadows/virtual/clipmap.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace shadowlab::vsm {
namespace {

bool powerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

}  // namespace

LightFrame LightFrame::towards(const glm::dvec3& direction) {
    LightFrame frame;
    frame.z = glm::normalize(direction);
    // World up unless the beam is nearly vertical; then world z, so that a sun overhead still
    // gets a frame (and the same one each time).
    const glm::dvec3 up = std::abs(frame.z.y) < 0.99 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
    frame.x = glm::normalize(glm::cross(up, frame.z));
    frame.y = glm::cross(frame.z, frame.x);
    return frame;
}

double ClipmapSettings::texelM(int level) const { return std::ldexp(2.0, level) / double(resolution); }

int32_t pageOf(double c, int pageTexels) {
    constexpr double kLimit = 1073741824.0;   // 2^30
    const double page = std::floor(c / double(pageTexels));   // exact: pageTexels is a power of two
    return int32_t(page > -kLimit ? (page < kLimit ? page : kLimit) : -kLimit);   // NaN: -2^30
}

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
    if (!powerOfTwo(s.pageTexels) || s.pageTexels < 8 || s.pageTexels > s.resolution / 2)
        fail("page-texels must be a power of two from 8 to half the resolution, got " + std::to_string(s.pageTexels));
    if (s.firstLevel < -40 || s.lastLevel > 40 || s.firstLevel > s.lastLevel)
        fail("levels must satisfy -40 <= first-level <= last-level <= 40, got " + std::to_string(s.firstLevel) +
             ".." + std::to_string(s.lastLevel));
}

}  // namespace shadowlab::vsm
