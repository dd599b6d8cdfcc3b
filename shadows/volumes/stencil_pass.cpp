#include "shadows/volumes/stencil_pass.h"

#include <algorithm>

#include "scenes/edge_adjacency.h"
#include "shadows/volumes/counting_mode.h"
#include "shadows/volumes/infinite_projection.h"
#include "shadows/world_draw.h"

namespace shadowlab {
namespace {

using raster::CompareFunc;
using raster::StencilOp;

// Step 2, taken first: step 1 builds the caps for z-fail only. Auto takes z-fail as well
// when a cut-out casts: the camera sees through its holes into its own volume, past its
// light cap, which z-pass does not draw, and z-fail counts behind the receiver instead.
void chooseCounting(const ShadowInputs& in, VolumeMode mode, const glm::dvec4& light, bool cutOutCasts,
                    StencilPass& pass) {
    pass.nearPlaneShadowed =
        nearPlaneMayBeShadowed(in.camera(), light, instanceBounds(in.casters().scene(), in.casterWorld()));
    switch (mode) {
        case VolumeMode::ZPass: pass.counting = VolumeCounting::ZPass; return;
        case VolumeMode::ZFail: pass.counting = VolumeCounting::ZFail; return;
        case VolumeMode::Auto: break;
    }
    pass.counting = pass.nearPlaneShadowed || cutOutCasts ? VolumeCounting::ZFail : VolumeCounting::ZPass;
}

// The camera's depth, as the G-buffer's camera pass (no culling, cut-outs with their holes),
// but with the far plane at infinity.
void depthPrepass(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const WorldGeometry& world,
                  const glm::mat4& clipFromWorld) {
    raster::PipelineState state;
    state.cull = raster::CullMode::None;
    state.clipFar = false;
    drawWorld(rasterizer, fb, state, world, clipFromWorld);
}

raster::PipelineState stencilPassState(VolumeCounting counting, float offsetUnits) {
    raster::PipelineState state;
    state.offset.units = offsetUnits;
    state.cull = raster::CullMode::None;
    state.clipFar = false;
    state.depth = {.test = true, .write = false, .func = CompareFunc::Less};
    state.stencil.enabled = true;
    if (counting == VolumeCounting::ZPass) {
        state.stencil.front.depthPass = StencilOp::IncrementWrap;
        state.stencil.back.depthPass = StencilOp::DecrementWrap;
    } else {
        state.stencil.back.depthFail = StencilOp::IncrementWrap;
        state.stencil.front.depthFail = StencilOp::DecrementWrap;
    }
    state.colorWriteMask = 0;
    return state;
}

// Every fragment of every volume face adds 1 to the red plane.
raster::PipelineState fillCountState() {
    raster::PipelineState state;
    state.cull = raster::CullMode::None;
    state.clipFar = false;
    state.depth = {.test = false, .write = false, .func = CompareFunc::Always};
    state.output = raster::FragmentOutput::ConstantColor;
    state.colorWriteMask = 0x1;
    state.blend = {.enabled = true, .equation = raster::BlendEquation::Add, .srcFactor = raster::BlendFactor::One,
                   .dstFactor = raster::BlendFactor::One};
    return state;
}

// Per WorldGeometry::cutOuts, whether it casts a volume (CutOutVolumes).
std::vector<uint8_t> castingCutOuts(const WorldGeometry& world, CutOutVolumes rule) {
    std::vector<uint8_t> casts;
    for (const WorldGeometry::CutOut& c : world.cutOuts) {
        const auto solid = size_t(std::count_if(c.alpha.begin(), c.alpha.end(), [&](float a) { return a >= c.cutoff; }));
        casts.push_back(rule == CutOutVolumes::Solid || (rule == CutOutVolumes::Coverage && 2 * solid >= c.alpha.size()));
    }
    return casts;
}

raster::DrawCall volumeDraw(const StencilPass& pass) {
    raster::DrawCall call;
    call.vertices.homogeneousPositions = pass.volume.vertices;
    call.triangles = pass.counting == VolumeCounting::ZPass ? pass.volume.sides() : pass.volume.all();
    call.clipFromObject = pass.clipFromWorld;
    return call;
}

}  // namespace

const SettingsTable<StencilPassSettings>& stencilPassSettingsTable() {
    using S = StencilPassSettings;
    static const auto table =
        SettingsTable<S>()
            .choice("mode", member(&S::mode),
                    {{"auto", VolumeMode::Auto, "z-fail when a volume may reach the near plane"},
                     {"zpass", VolumeMode::ZPass},
                     {"zfail", VolumeMode::ZFail}})
            .real("offset", member(&S::offsetUnits), 0.0, 64.0,
                  "polygon offset of the volume faces, in units of the depth buffer's resolution")
            .choice("cut-outs", member(&S::cutOuts),
                    {{"coverage", CutOutVolumes::Coverage,
                      "a cut-out casts its whole triangles if at least half its texels are solid, else nothing"},
                     {"solid", CutOutVolumes::Solid, "every cut-out casts its whole triangles"},
                     {"none", CutOutVolumes::None, "cut-outs cast nothing"}},
                    "what the volume, made of whole triangles, does with an alpha-tested card (docs/cut-outs.md)");
    return table;
}

// Steps 1 to 4; the stencil pass's fragments are the fill (step 5).
StencilPass runStencilPass(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const ShadowInputs& in,
                           const StencilPassSettings& settings, const glm::dvec4& light, StageTimer& timer) {
    StencilPass pass;
    pass.offsetUnits = settings.offsetUnits;
    const std::vector<uint8_t> cutOutCasts = castingCutOuts(in.casterWorld(), settings.cutOuts);
    chooseCounting(in, settings.mode, light, std::ranges::find(cutOutCasts, 1) != cutOutCasts.end(), pass);
    pass.volume = extrudeShadowVolume(in.casters().scene(), in.casterWorld(), in.casters().edgeAdjacency(), light,
                                      pass.counting == VolumeCounting::ZFail, cutOutCasts);
    timer.lap("extrusion");

    pass.clipFromWorld = clipFromWorldInfinite(in.camera());
    fb.clearDepth(1.0f), fb.clearStencil(0);
    depthPrepass(rasterizer, fb, in.receiverWorld(), pass.clipFromWorld);
    rasterizer.resetStats();
    rasterizer.draw(fb, stencilPassState(pass.counting, pass.offsetUnits), volumeDraw(pass));
    pass.fill = rasterizer.stats();
    timer.lap("stencil");
    return pass;
}

// Sides are extruded two triangles per silhouette edge, in silhouette order
// (volume_extrusion.cpp), so edge k owns side triangles 2k and 2k + 1.
void listSideFragments(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const StencilPass& pass,
                       std::span<const uint32_t> edges) {
    std::vector<glm::uvec3> triangles;
    std::vector<uint32_t> ids;
    const std::span<const glm::uvec3> sides = pass.volume.sides();
    for (const uint32_t e : edges) {
        triangles.insert(triangles.end(), {sides[2 * e], sides[2 * e + 1]});
        ids.insert(ids.end(), {e, e});
    }
    raster::PipelineState state = stencilPassState(pass.counting, pass.offsetUnits);
    state.stencil.enabled = false;
    state.output = raster::FragmentOutput::FragmentList;
    raster::DrawCall call = volumeDraw(pass);
    call.triangles = triangles;
    call.primitiveIds = ids;
    fb.clearFragments();
    rasterizer.draw(fb, state, call);
}

std::vector<float> fillPerPixel(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const StencilPass& pass) {
    fb.clearColor(glm::vec4(0.0f));
    rasterizer.draw(fb, fillCountState(), volumeDraw(pass));
    return fb.colorImage(0);
}

void appendStencilPassStats(const ShadowInputs& in, const StencilPass& pass, std::vector<TechniqueStat>& stats) {
    uint32_t openMeshes = 0, openEdges = 0, nonManifoldEdges = 0;
    for (const MeshInstance& instance : in.casters().scene().instances) {
        const EdgeAdjacency& a = in.casters().edgeAdjacency()[instance.mesh];
        openMeshes += !a.closed, openEdges += a.openEdges, nonManifoldEdges += a.nonManifoldEdges;
    }
    const double fragments = double(pass.fill.fragments);
    stats.insert(stats.end(), {
        {"zfail_flag", pass.counting == VolumeCounting::ZFail ? 1.0 : 0.0},
        {"near_plane_shadowed_flag", pass.nearPlaneShadowed ? 1.0 : 0.0},
        {"open_instances_count", double(openMeshes)},
        {"open_edges", double(openEdges)},
        {"non_manifold_edges", double(nonManifoldEdges)},
        {"silhouette_edges", double(pass.volume.silhouette.size())},
        {"volume_side_triangles", double(pass.volume.sideCount)},
        {"volume_light_cap_triangles", double(pass.volume.lightCapCount)},
        {"volume_dark_cap_triangles", double(pass.volume.darkCapCount)},
        {"volume_set_up_triangles", double(pass.fill.trianglesSetUp)},
        {"fill_fragments", fragments},
        {"fill_fragments_per_pixel", fragments / double(in.gbuffer.pixelCount())},
    });
}

}  // namespace shadowlab
