#include "shading/environment/environment_debug.h"

namespace shadowlab {

std::vector<glm::vec3> shImage(const EnvironmentMap& map, const ShCoefficients& coefficients, double scale) {
    std::vector<glm::vec3> image(map.radiance.size());
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const glm::dvec3 d = map.direction((i + 0.5) / map.width, (j + 0.5) / map.height);
            image[size_t(j) * size_t(map.width) + size_t(i)] = glm::vec3(scale * evaluateSh(coefficients, d));
        }
    }
    return image;
}

std::vector<uint8_t> lightsImage(const EnvironmentMap& map, const std::vector<EnvironmentLight>& lights,
                                 const std::vector<uint32_t>& regionOfTexel, const ToneMapOptions& tone) {
    std::vector<uint8_t> rgb = toSrgb8Image(map.radiance, tone);
    const auto paint = [&](int i, int j, glm::u8vec3 colour) {
        if (i < 0 || j < 0 || i >= map.width || j >= map.height) return;
        uint8_t* p = &rgb[3 * (size_t(j) * size_t(map.width) + size_t(i))];
        p[0] = colour.r, p[1] = colour.g, p[2] = colour.b;
    };
    const glm::u8vec3 grey(128, 128, 128), red(255, 0, 0);
    const auto regionAt = [&](int i, int j) { return regionOfTexel[size_t(j) * size_t(map.width) + size_t(i)]; };
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const bool edge = (i + 1 < map.width && regionAt(i + 1, j) != regionAt(i, j)) ||
                              (j + 1 < map.height && regionAt(i, j + 1) != regionAt(i, j));
            if (edge) paint(i, j, grey);
        }
    }
    for (const EnvironmentLight& l : lights) {
        const glm::ivec2 t = map.texelToward(l.direction);
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) paint(t.x + di, t.y + dj, red);
    }
    return rgb;
}

}  // namespace shadowlab
