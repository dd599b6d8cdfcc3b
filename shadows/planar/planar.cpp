// `planar`: planar projected shadows (Blinn 1988, "Me and My (Fake) Shadow"; RTR 4th ed.,
// section 7.1.1; Lehtinen 2015, "Cast Shadows on Planar Surfaces"). Every occluder is drawn
// a second time squashed onto the receiver plane y = plane-y by the planar projection
// matrix, as dark translucent geometry. Passes, into one colour + stencil framebuffer:
//
//   1. depth prepass of the scene with the camera's matrix (the G-buffer's depths);
//   2. receiver pass: the instances lying in the plane, depth test LessEqual and no
//      writes, set the stencil of their visible pixels to 0 (it is cleared to 255, "no
//      receiver"), so the shadow lands only on the visible plane, never on an object in
//      front of it or past the plane's edge;
//   3. shadow pass: every other instance through clipFromWorld * M, colour (0, 0, 0,
//      opacity) blended over white, stencil test equal 0 with increment: the first
//      fragment at a pixel blends and lifts the stencil to 1, so overlapping projected
//      triangles never darken a pixel twice (RTR 7.1.1, "to avoid double blending").
//
// V = 0 where the stencil is 1 (a receiver pixel the projected shadow covers) and outside
// a spot light's cone, 1 on every other surface. Known failure modes, kept visible on purpose and asserted by the tests:
//   - no self-shadowing and no shadows on non-planar receivers: the sphere's unlit side
//     and the box's shadow on the sphere get V = 1 (the image still darkens the unlit side
//     through its N.L factor; the V buffer does not);
//   - receivers below or beside the plane, and objects under it, receive nothing;
//   - triangles with a vertex as far from the plane as the light, or farther, are not
//     drawn: M would send them through w <= 0 and cast "anti-shadows" (RTR 7.1.1); the part
//     of an occluder below the plane is projected too (hidden under the occluder as long
//     as the occluder stands on the plane).
#include "shadows/planar/planar.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "raster/rasterizer.h"
#include "scenes/camera.h"
#include "shading/lights.h"
#include "shadows/debug_buffers.h"
#include "shadows/kept_raster.h"
#include "shadows/settings_table.h"
#include "shadows/silhouettes/silhouette.h"
#include "shadows/stage_timer.h"
#include "shadows/world_draw.h"

namespace shadowlab {
namespace {

struct PlanarSettings {
    double planeY = 0.0;    // the receiver plane y = planeY, m
    float opacity = 0.6f;   // the debug image's shadow alpha
};

const SettingsTable<PlanarSettings>& planarSettingsTable() {
    using S = PlanarSettings;
    static const auto table =
        SettingsTable<S>()
            .real("plane-y", member(&S::planeY), -1e6, 1e6, "height of the receiver plane y = plane-y, in metres")
            .real("opacity", member(&S::opacity), 0.0, 1.0,
                  "alpha of the dark translucent shadow in the debug image; V does not depend on it");
    return table;
}

using raster::CompareFunc;
using raster::StencilOp;

constexpr uint8_t kNoReceiver = 0xff;   // stencil clear value
constexpr uint8_t kShadowed = 1;        // a receiver pixel after one shadow fragment

// A vertex belongs to the plane when its distance is within this fraction of its size
// (plus 1 um): far above float rounding of instance transforms (2^-24 relative), far
// below any gap between an object and the ground that matters in the scenes.
constexpr double kOnPlaneTolerance = 1e-6;

bool onPlane(const glm::dvec4& plane, const glm::vec3& p) {
    const double distance = glm::dot(plane, glm::dvec4(glm::dvec3(p), 1.0));
    return std::abs(distance) <= kOnPlaneTolerance * std::max(1.0, double(glm::length(p)));
}

// Instances entirely in the plane receive, the others cast: decided once, on the scene the
// camera sees (the casters' copy, ShadowInputs::casters, has the same instances).
std::vector<uint8_t> receivingInstances(const Scene& scene, const WorldGeometry& world, const glm::dvec4& plane) {
    std::vector<uint8_t> receiving;
    for (const InstanceRange& r : instanceRanges(scene)) {
        const auto vertices = std::span(world.positions).subspan(r.firstVertex, scene.meshes[r.mesh].positions.size());
        receiving.push_back(std::all_of(vertices.begin(), vertices.end(), [&](const glm::vec3& p) { return onPlane(plane, p); }));
    }
    return receiving;
}

enum class PlanarRole { Receiver, Caster };

// The triangles of the instances in that role (indices into the world's triangles, in
// order), from that role's scene and world; a caster less its triangles that reach the
// light's distance from the plane.
std::vector<uint32_t> trianglesOf(PlanarRole role, const Scene& scene, const WorldGeometry& world,
                                    std::span<const uint8_t> receiving, const glm::dvec4& plane, const glm::dvec4& light) {
    const double lightHeight = glm::dot(plane, light);   // for w = 0: > 0 means above, never reached
    auto belowLight = [&](uint32_t v) {
        return light.w == 0.0 || glm::dot(plane, glm::dvec4(glm::dvec3(world.positions[v]), 1.0)) < lightHeight;
    };
    const std::vector<InstanceRange> ranges = instanceRanges(scene);
    std::vector<uint32_t> out;
    for (size_t i = 0; i < ranges.size(); ++i) {
        if (bool(receiving[i]) != (role == PlanarRole::Receiver)) continue;
        for (uint32_t k = 0; k < ranges[i].triangleCount; ++k) {
            const uint32_t index = ranges[i].firstTriangle + k;
            const glm::uvec3& t = world.triangles[index];
            if (receiving[i] || (belowLight(t.x) && belowLight(t.y) && belowLight(t.z))) out.push_back(index);
        }
    }
    return out;
}

raster::PipelineState prepassState() {
    raster::PipelineState state;
    state.cull = raster::CullMode::None;
    return state;
}

raster::PipelineState receiverState() {
    raster::PipelineState state = prepassState();
    state.depth = {.test = true, .write = false, .func = CompareFunc::LessEqual};
    state.stencil.enabled = true;
    state.stencil.front.depthPass = state.stencil.back.depthPass = StencilOp::Zero;
    state.colorWriteMask = 0;
    return state;
}

raster::PipelineState shadowState() {
    raster::PipelineState state = prepassState();
    state.depth = {.test = false, .write = false, .func = CompareFunc::Always};
    state.stencil.enabled = true;
    state.stencil.front.func = state.stencil.back.func = CompareFunc::Equal;   // reference 0
    state.stencil.front.depthPass = state.stencil.back.depthPass = StencilOp::Increment;
    state.output = raster::FragmentOutput::ConstantColor;
    state.blend = {.enabled = true, .equation = raster::BlendEquation::Add,
                   .srcFactor = raster::BlendFactor::SrcAlpha, .dstFactor = raster::BlendFactor::OneMinusSrcAlpha};
    return state;
}

// The stencil pass's framebuffer memory and rasterizer, kept between frames (kept_raster.h).
struct PlanarBuffers {
    raster::FramebufferStorage memory;
    KeptRasterizer rasterizer;
};

ShadowOutputs runPlanar(const ShadowInputs& in) {
    const PlanarSettings settings = planarSettingsTable().read(in.params);
    const Camera& camera = in.camera();
    const glm::dvec4 plane(0.0, 1.0, 0.0, -settings.planeY);
    const glm::dvec4 light = homogeneousLight(pointLightFor(in.light));
    StageTimer timer;
    const std::vector<uint8_t> receiving = receivingInstances(in.scene(), in.receiverWorld(), plane);
    const std::vector<uint32_t> receivers =
        trianglesOf(PlanarRole::Receiver, in.scene(), in.receiverWorld(), receiving, plane, light);
    const std::vector<uint32_t> casters =
        trianglesOf(PlanarRole::Caster, in.casters().scene(), in.casterWorld(), receiving, plane, light);
    timer.lap("split");

    const glm::dmat4 cameraFromWorld = clipFromWorldD(camera);
    const glm::mat4 clipFromWorld(cameraFromWorld);
    const glm::mat4 clipFromShadow(cameraFromWorld * planarProjection(plane, light));
    PlanarBuffers& kept = in.kept().state<PlanarBuffers>();
    KeptFramebuffer framebuffer(kept.memory, camera.width, camera.height, {.stencil = true, .color = true});
    raster::Framebuffer& fb = *framebuffer;
    fb.clearDepth(1.0f), fb.clearStencil(kNoReceiver), fb.clearColor(glm::vec4(1.0f));
    raster::Rasterizer& rasterizer = kept.rasterizer.at(in.simd);
    // Cut-outs with their holes in every pass (world_draw.h): the prepass's depth is the
    // G-buffer's, and a projected card's texture coordinates interpolate as on the card
    // (M is projective), so its shadow has the shape of its leaves.
    drawWorld(rasterizer, fb, prepassState(), in.receiverWorld(), clipFromWorld);
    // (An empty list would draw the whole world.)
    if (!receivers.empty()) drawWorld(rasterizer, fb, receiverState(), in.receiverWorld(), clipFromWorld, receivers);
    if (!casters.empty()) {
        drawWorld(rasterizer, fb, shadowState(), in.casterWorld(), clipFromShadow, casters,
                  glm::vec4(0.0f, 0.0f, 0.0f, settings.opacity));
    }
    timer.lap("stencil");

    // The stencil read in place (block-linear), rows in parallel; the counts are integer
    // sums, the same in any order.
    const uint8_t* stencil = fb.stencil().data();
    const GBuffer& g = in.gbuffer;
    ShadowOutputs out;
    out.visibility.assign(g.pixelCount(), 0.0f);
    out.stencil.resize(g.pixelCount());
    using Counts = std::pair<size_t, size_t>;   // receiver pixels, shadowed ones
    const Counts counts = tbb::parallel_reduce(
        tbb::blocked_range<int>(0, g.height), Counts{0, 0},
        [&](const tbb::blocked_range<int>& rows, Counts c) {
            for (int j = rows.begin(); j < rows.end(); ++j) {
                for (int x0 = 0; x0 < g.width; x0 += raster::kBlockSize) {
                    // A block's row of pixels is contiguous: one storage index per block.
                    const uint8_t* run = stencil + fb.index(x0, j);
                    for (int i = x0; i < std::min(x0 + raster::kBlockSize, g.width); ++i) {
                        const size_t k = g.index(i, j);
                        const uint8_t s = run[i - x0];
                        out.stencil[k] = float(s);
                        // Outside a spot's cone no light arrives (the V convention), shadow or not.
                        const bool inCone = in.light.type != LightType::Spot || insideSpotCone(in.light, g.position[k]);
                        out.visibility[k] = g.hit[k] && inCone && s != kShadowed ? 1.0f : 0.0f;
                        c.first += s != kNoReceiver;
                        c.second += s == kShadowed;
                    }
                }
            }
            return c;
        },
        [](Counts a, Counts b) { return Counts{a.first + b.first, a.second + b.second}; });
    const double receiverPixels = double(counts.first), shadowed = double(counts.second);
    out.stats = {
        {"receiver_triangles", double(receivers.size())},
        {"caster_triangles", double(casters.size())},
        {"receiver_pixels", receiverPixels},
        {"shadowed_receiver_pixels", shadowed},
    };
    timer.lap("visibility");
    timer.appendTo(out.stats);
    const DebugBuffers debug(in.debugDir, "planar");
    if (debug.enabled()) {
        debug.write("shadow", camera.width, camera.height, fb.colorImage(0), 0.0f, 1.0f);
        debug.write("stencil", camera.width, camera.height, out.stencil, 0.0f, 2.0f);
    }
    return out;
}

}  // namespace

glm::dmat4 planarProjection(const glm::dvec4& plane, const glm::dvec4& light) {
    glm::dmat4 m(glm::dot(plane, light));   // dot(pi, l) I
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) m[column][row] -= light[row] * plane[column];
    }
    return m;
}

Technique planarTechnique() {
    return {.name = "planar",
            .description = "planar projected shadows on the plane y = plane-y, stencil against double "
                           "blending (no self-shadows)",
            .params = planarSettingsTable().specs(),
            .run = runPlanar,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
