// The shadow-map family on every hard case (docs/hard-cases.md): either within its bound
// (errors only in the band around the reference's shadow boundary that the map's texel
// footprint explains, and few of them), or the known failure mode, asserted.
#include <doctest/doctest.h>

#include "tests/shadows/maps/shadow_map_test_util.h"

using namespace shadowlab;

namespace {

struct HardCase {
    const char* scene;
    const char* technique;      // shadow-map, or csm / lispsm on the directional case
    double maxPercent;          // misclassified, % of hit pixels
    double maxOffBandPercent;   // errors farther than the texel-footprint band from a reference boundary
    const char* knownFailure;   // empty when the technique handles the case
};

// Defaults (resolution 2048, slope-scaled bias). Measured 2026-11-22: at most 0.06%
// misclassified and 0.013% off the band on the handled cases; the bounds leave room.
const HardCase kCases[] = {
    {"grazing-light", "shadow-map", 0.2, 0.02, ""},
    {"thin-occluder", "shadow-map", 0.2, 0.02, ""},
    {"camera-in-shadow", "shadow-map", 0.2, 0.02, ""},
    {"near-plane-cuts-volume", "shadow-map", 0.2, 0.02, ""},
    {"sphere-terminator", "shadow-map", 0.2, 0.02, ""},
    {"coincident-faces", "shadow-map", 0.2, 0.02, ""},
    {"point-light-inside", "shadow-map", 0.2, 0.02, ""},
    {"sun", "shadow-map", 0.2, 0.02, ""},
    // Cascades and the LiSPSM warp need a directional light: the sun is their case.
    {"sun", "csm", 0.2, 0.02, ""},
    {"sun", "lispsm", 0.2, 0.02, ""},
    {"spot", "shadow-map", 0.2, 0.02, ""},
    // The first-depth map keeps both facings, so the open teapot's inside, seen by the
    // light through the opening, casts too (with back faces culled its handle leaked).
    {"open-mesh", "shadow-map", 0.2, 0.02, ""},
    // The pillar's top face, 5 cm from the light, shadows itself (acne): that close, the
    // float rounding of the receiver's position is a large fraction of what a texel's depth
    // resolves, beyond what a bias in texels and depth units covers.
    {"light-close", "shadow-map", 0.2, 1.0, "acne on the face nearest the light"},
    // One 2048 map over 10 km of depth: near occluders' shadows fall between texels and
    // vanish (about 2% of the image lit wrongly). Cascades exist for this.
    {"huge-depth-range", "shadow-map", 10.0, 10.0, "near shadows lost to texel size over a 10 km frustum"},
};

}  // namespace

TEST_CASE("shadow-map on every hard case: within its bound, or its known failure") {
    for (const HardCase& c : kCases) {
        const std::string name = c.scene;
        const Scene scene = loadScene(builtinSceneDir() + "/hard/" + name + ".json");
        const PreparedScene prepared(scene);
        const Frame reference = test::frameOf(prepared, "reference");
        const std::string technique = c.technique;
        const Frame sm = technique == "lispsm" ? test::frameOf(prepared, "shadow-map", {{"warp", "lispsm"}})
                                               : test::frameOf(prepared, technique);
        const int band = test::leakBandPixels(test::statOf(sm, "median_texels_per_pixel"));
        const test::BandedErrors m = test::bandedErrors(reference, sm, band);
        const double hit = m.lit + m.shadowed;
        const double percent = 100.0 * (m.falseShadow + m.falseLight) / hit;
        const double offBand = 100.0 * (m.falseShadowOffBoundary + m.falseLightOffBoundary) / hit;
        INFO(name << ", " << technique << ": " << percent << "% misclassified (" << m.falseShadow << " false shadow, " << m.falseLight
                  << " false light), " << offBand << "% off the " << band << "-pixel band");
        CHECK(percent <= c.maxPercent);
        CHECK(offBand <= c.maxOffBandPercent);
        // Receivers on every side of the light: a map on each of the six cube faces.
        if (name == "point-light-inside") CHECK(test::statOf(sm, "maps_count") == 6.0);
        const std::string failure = c.knownFailure;
        if (failure.empty()) continue;
        // The known failure is asserted to be there: a change that cures it must update this.
        INFO("known failure: " << failure);
        if (name == "light-close") CHECK(m.falseShadowOffBoundary > 0);
        if (name == "huge-depth-range") CHECK(100.0 * m.falseLight / hit > 1.0);
    }
}
