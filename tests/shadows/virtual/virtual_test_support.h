// What the virtual shadow map's tests share: a small map's settings, and a sequence of
// frames with the technique's history kept from one to the next beside frames alone.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "frame/registry.h"
#include "frame/render.h"
#include "scenes/prepared_scene.h"
#include "tests/shadows/shadow_test_support.h"

namespace shadowlab::test {

// A small virtual map (4096 texels a level, or a local light's face at mip 0, in pages of
// 64) so that the tests stay quick; `more` adds or overrides settings.
inline std::map<std::string, std::string> smallVirtualMap(std::map<std::string, std::string> more = {}) {
    more.emplace("virtual-resolution", "4096");
    more.emplace("page-texels", "64");
    return more;
}

// A frame whose pool could not hold the pages it requested: some overflowed, their pixels
// were counted, and each of those reads lit.
inline void checkOverflowedIntoLitPixels(const ShadowOutputs& out) {
    CHECK(stat(out, "cache_overflowed_pages") > 0);
    CHECK(stat(out, "cache_missing_pixels") > 0);
    size_t lit = 0;
    for (float v : out.visibility) lit += v == 1.0f;
    CHECK(lit >= size_t(stat(out, "cache_missing_pixels")));
}

// Frames of `virtual-shadow-map` with `params` over one prepared scene: next() continues the
// kept history, alone() renders the same frame without one.
struct KeptFrames {
    PreparedScene prepared;
    std::map<std::string, std::string> params;
    const Technique& vsm = findTechnique("virtual-shadow-map");
    FrameHistory history;

    KeptFrames(Scene scene, std::map<std::string, std::string> settings)
        : prepared(std::move(scene)), params(std::move(settings)) {}

    Frame next() { return renderFrame(prepared, vsm, settings(&history)); }
    std::vector<float> alone() const { return renderFrame(prepared, vsm, settings(nullptr)).shadow.visibility; }

    // Moves instance `index` by `offset`, m, in world space.
    void move(uint32_t index, const glm::vec3& offset) {
        const InstancePlacement placement{
            index, glm::translate(glm::mat4(1.0f), offset) * prepared.scene().instances[index].worldFromObject};
        REQUIRE(prepared.setInstanceTransforms({&placement, 1}) == 1);
    }

private:
    FrameSettings settings(FrameHistory* kept) const {
        FrameSettings s;
        s.params = params;
        s.history = kept;
        return s;
    }
};

}  // namespace shadowlab::test
