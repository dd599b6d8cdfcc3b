// The shadow techniques `shadowlab render --technique NAME` can run. Each takes the
// G-buffer of the camera view and the selected light and returns either the visibility V
// of that light at every pixel (conventions.md), which the frame then shades, or a shaded
// radiance image of its own (a technique that lights the scene with many lights at once);
// plus figures about its work (stats) and any intermediate buffers it can show.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raster/tile_kernels.h"
#include "scenes/prepared_scene.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shading/motion_vectors.h"
#include "shadows/progress.h"
#include "shadows/technique_history.h"
#include "shadows/technique_params.h"

namespace shadowlab {

// Built by name, the fields left out taking their defaults:
//   technique.run({.prepared = p, .gbuffer = g, .light = l, .simd = s, .params = params});
struct ShadowInputs {
    const PreparedScene& prepared;         // the scene the camera sees: receivers, materials, lights
    const GBuffer& gbuffer;
    const Light& light;                    // the selected light
    raster::SimdLevel simd;
    const TechniqueParams& params;         // the technique's level-of-detail settings
    std::filesystem::path debugDir = {};   // empty: write no intermediate buffers
    Progress* progress = nullptr;          // where a slow technique reports; null: nowhere
    // The camera the G-buffer was built with; null: the scene's. A technique that lights
    // the scene from many lights may run another technique on a smaller G-buffer of the same
    // view (subtractive shadows at a lower sampling detail), whose camera it names here.
    const Camera* gbufferCamera = nullptr;
    // What casts the shadows; null: `prepared` itself. At a caster level of detail below 1
    // (the frame's `caster-lod`, scenes/caster_lod.h) its simplified copy, of which only
    // the geometry is read: what a technique draws into a light's view, extrudes or traces
    // comes from casters(), what it shades or compares against (the G-buffer's surfaces)
    // from receiverWorld().
    const PreparedScene* casterScene = nullptr;
    // How far each instance's surfaces in the G-buffer were lifted along their normals
    // against the casters' simplification (camera_pass.h, liftedReceivers()), m, indexed
    // like Scene::instances; empty with whole casters. A technique that renders a G-buffer
    // of its own lifts it alike.
    std::span<const float> receiverLiftM = {};
    // What the technique keeps for the next frame of a sequence (technique_history.h): the
    // caller's, one per light of its series; null: the frame stands alone, and kept() gives
    // it a history that ends with these inputs.
    TechniqueHistory* history = nullptr;
    // The frame's place in its sequence: 0 for a frame that stands alone and a sequence's
    // first, then one more each frame (what a per-frame noise pattern advances with).
    uint64_t frameIndex = 0;
    // The view of the frame before, which gbuffer.motion points into; null where frameIndex
    // is 0. A temporal technique reprojects its own result of that frame with the two
    // (shadows/temporal/reprojection.h).
    const PreviousView* previous = nullptr;

    const Scene& scene() const { return prepared.scene(); }
    const WorldGeometry& receiverWorld() const { return prepared.world(); }
    const PreparedScene& casters() const { return casterScene ? *casterScene : prepared; }
    const WorldGeometry& casterWorld() const { return casters().world(); }
    const Camera& camera() const { return gbufferCamera ? *gbufferCamera : prepared.scene().camera; }

    // The history to keep state in: `history`, or for a frame that stands alone one of its
    // own, which copies of these inputs share. Call it from the technique's own thread, as
    // TechniqueHistory::state.
    TechniqueHistory& kept() const { return history ? *history : *standalone_; }
    std::shared_ptr<TechniqueHistory> standalone_ = std::make_shared<TechniqueHistory>();   // kept()'s; never set
};

// A named figure a technique reports about its own work (texels, fill, list lengths...).
// Names are snake_case and end in their unit (docs/architecture.md, "Stat names"):
// `fill_fragments_per_pixel`, `silhouette_ms`, `light_near_m`, `zfail_flag`.
struct TechniqueStat {
    std::string name;
    double value;
};

struct ShadowOutputs {
    std::vector<float> visibility;         // V per pixel, row-major, 0 where hit = 0
    // The light passed per channel where casters are tinted (conventions.md, "Casters that
    // are not opaque"), shaded in place of V; empty for a technique that sees no colour.
    // V is then its luminance.
    std::vector<glm::vec3> colouredVisibility;
    std::vector<glm::vec3> radiance;       // TechniqueOutput::Radiance only: linear, row-major
    std::vector<float> stencil;            // per pixel, empty if the technique uses no stencil
    std::vector<TechniqueStat> stats;
};

// What a technique returns and is scored on: V (the frame shades it with the selected
// light) or radiance (the technique's own shaded image, scored on its luminance).
enum class TechniqueOutput { Visibility, Radiance };

struct Technique {
    std::string name;
    std::string description;
    std::vector<ParamSpec> params;
    std::function<ShadowOutputs(const ShadowInputs&)> run;
    // The technique this one is scored against (`render --error-map`, `sweep`), of the same
    // output: `reference`, the hard shadow of the light's centre, for hard-shadow
    // techniques; `reference-soft`, the visible fraction of an area light, for soft ones.
    std::string referenceName = "reference";
    TechniqueOutput output = TechniqueOutput::Visibility;
    // Whether, at its default settings, a frame of a sequence depends on the frames before
    // (it reads its own past results, or its noise moves with the frame: docs/temporal.md),
    // so that only a sequence's first frame is a frame alone. False: what it keeps between
    // frames is memory and caches, and every frame gives the bytes of a frame alone.
    bool temporal = false;
    // Scene preparation the technique reads with these settings (the casters' edge
    // adjacency, an environment's tables): the frame calls it with the scene and its casters
    // (ShadowInputs::casters) before the technique's time starts (frame/render.h), so that
    // what an engine builds at load time is not counted in a frame. It builds what is
    // missing, once per prepared scene, and returns the wall time of what it built
    // (`<what>_ms`), nothing when all was built already. Null: none.
    std::function<std::vector<TechniqueStat>(const PreparedScene& prepared, const PreparedScene& casters,
                                             const TechniqueParams&)>
        prepare = nullptr;
};

// Shadow level of detail by geometry (scenes/caster_lod.h): `caster-lod`, the share of
// the casters' triangles kept, a parameter the registry gives every technique that draws
// casters (not the references, not `unshadowed`). The frame reads it, not the technique:
// it simplifies the casters (once per ratio) and passes them as ShadowInputs::casters.
Technique withCasterLod(Technique technique);
bool hasCasterLod(const Technique& technique);
// The ratio the settings ask for; 1 for a technique without the parameter.
double casterLodRatio(const TechniqueParams& params);

// The casters' edge adjacency (silhouettes), built once: `edge_adjacency_ms` if built now.
std::vector<TechniqueStat> prepareCasterEdgeAdjacency(const PreparedScene& casters);
// Technique::prepare of the techniques that read it.
std::vector<TechniqueStat> prepareEdgeAdjacency(const PreparedScene& prepared, const PreparedScene& casters,
                                                const TechniqueParams& params);

// A view in which the light reaches no surface (none seen, or every one it sees behind the
// light, facing away or outside a spot's cone: lightReaches, shading/lights.h) has one
// answer, V = 0 everywhere (conventions.md, the V channel). A technique that fits a light's
// view to its receivers (an error with none, light_view.h) checks its settings and light
// first, so that they fail alike on every view, then returns unlitOutputs(): so a frame of
// many lights (docs/many-lights.md) takes a spot that lights nothing in view.
// anySurface: whether the view sees any surface at all.
bool anySurface(const GBuffer& g);
bool anyReachable(const GBuffer& g, const Light& light);
ShadowOutputs unlitOutputs(const GBuffer& g);

// Hard-shadow techniques see a light as a point: an area light's centre stands in for it,
// and a sun with an angular size is a point-like sun in its centre direction.
// The result is for visibility only (its intensity keeps the area light's units).
Light pointLightFor(const Light& light);

}  // namespace shadowlab
