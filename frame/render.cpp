#include "frame/render.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "scenes/camera.h"
#include "scenes/caster_lod.h"
#include "scenes/scene_limits.h"
#include "shading/shade.h"

namespace shadowlab {
namespace {

// A position given on the command line, bound as a scene file's are (scene_limits.h).
void requireCoordinate(const glm::vec3& v, const char* what) {
    const auto inWorld = [](float x) { return std::abs(double(x)) <= kMaxCoordinate; };   // false for NaN
    if (!inWorld(v.x) || !inWorld(v.y) || !inWorld(v.z)) {
        throw std::invalid_argument(std::string(what) + " must be three numbers within +-" +
                                    (std::ostringstream() << kMaxCoordinate).str() + " metres");
    }
}

// Only a disk has a radius: giving one to a point light would silently change nothing.
void applyLightRadius(Scene& scene, float radius) {
    if (!(radius > 0.0f && std::isfinite(radius)))
        throw std::invalid_argument("--light-radius must be a finite number > 0, got " + (std::ostringstream() << radius).str());
    if (scene.lights.empty()) throw std::invalid_argument("--light-radius: the scene has no light");
    if (scene.lights[0].type != LightType::Disk)
        throw std::invalid_argument("--light-radius: the scene's first light is not a disk light");
    scene.lights[0].radius = radius;
}

// The casters at the settings' level of detail; their simplification, the first time a
// ratio is asked for, is scene preparation (caster_lod_ms), outside the technique's time.
CasterLevel prepareCasters(const PreparedScene& prepared, const TechniqueParams& params,
                           std::vector<TechniqueStat>& preparation) {
    std::optional<double> ms;
    const CasterLevel level = casterLevel(prepared, casterLodRatio(params), &ms);
    if (ms) preparation.push_back({"caster_lod_ms", *ms});
    return level;
}

// `--light N`: the scene keeps that light alone.
void selectLight(Scene& scene, int index) {
    const int count = int(scene.lights.size());
    if (index >= 0 && index < count) {
        scene.lights = {scene.lights[size_t(index)]};
        return;
    }
    std::string lights = std::to_string(count) + (count == 1 ? " light (index 0)" : " lights");
    if (count > 1) lights += " (indices 0.." + std::to_string(count - 1) + ")";
    throw std::invalid_argument("--light " + std::to_string(index) + ": the scene has " + lights);
}

// Runs the technique for one light, timed alone (the time a frame reports). Among several
// lights, a light the technique cannot take is named ("light 1: csm: needs a directional
// light"), so that the user knows which to leave out with --light.
LightPass runPass(const Technique& technique, const ShadowInputs& inputs, size_t lightIndex, size_t passCount) {
    LightPass pass;
    pass.light = lightIndex;
    const auto start = std::chrono::steady_clock::now();
    try {
        pass.shadow = technique.run(inputs);
    } catch (const std::invalid_argument& e) {
        if (passCount == 1) throw;
        throw std::invalid_argument("light " + std::to_string(lightIndex) + ": " + e.what());
    }
    pass.techniqueMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return pass;
}

// Each light's intermediate buffers in a folder of its own when there are several.
std::filesystem::path passDebugDir(const std::filesystem::path& debugDir, size_t passCount, size_t k) {
    if (debugDir.empty() || passCount == 1) return debugDir;
    return debugDir / lightDebugFolder(k);
}

// A frame of several passes: the first pass's buffers, and every pass's stats as lightK_NAME
// with lightK_technique_ms its time (render.h, Frame::shadow).
ShadowOutputs framedOutputs(const std::vector<LightPass>& passes) {
    if (passes.size() == 1) return passes.front().shadow;
    ShadowOutputs out = passes.front().shadow;
    out.stats.clear();
    for (const LightPass& pass : passes) {
        const std::string prefix = "light" + std::to_string(pass.light) + "_";
        out.stats.push_back({prefix + "technique_ms", pass.techniqueMs});
        for (const TechniqueStat& s : pass.shadow.stats) out.stats.push_back({prefix + s.name, s.value});
    }
    return out;
}

std::vector<glm::vec3> shadePasses(const Scene& scene, const GBuffer& gbuffer, const std::vector<LightPass>& passes) {
    std::vector<ShadedLight> lights;
    for (const LightPass& pass : passes)
        lights.push_back({pass.light, pass.shadow.visibility, pass.shadow.colouredVisibility});
    return shade(scene, gbuffer, lights);
}

}  // namespace

std::string lightDebugFolder(size_t light) { return "light" + std::to_string(light); }

TechniqueHistory& FrameHistory::pass(const PreparedScene& prepared, const Technique& technique,
                                     const std::map<std::string, std::string>& params, size_t light) {
    const Owner owner{&prepared, technique.name, params};
    if (!owner_) owner_ = owner;
    if (*owner_ != owner)
        throw std::logic_error("a frame history of " + owner_->technique + " was given a frame of " + technique.name +
                               ", another scene or other settings: keep one history per series");
    if (light >= passes_.size()) passes_.resize(light + 1);
    return passes_[light];
}

void applyOverrides(Scene& scene, const SceneOverrides& o) {
    if (o.light) selectLight(scene, *o.light);
    Camera& c = scene.camera;
    if (o.width) c.width = *o.width;
    if (o.height) c.height = *o.height;
    if (o.eye) requireCoordinate(*o.eye, "--eye"), c.eye = *o.eye;
    if (o.target) requireCoordinate(*o.target, "--target"), c.target = *o.target;
    if (o.fovyDeg) c.fovyDeg = *o.fovyDeg;
    if (c.width < 1 || c.height < 1 || c.width > raster::kMaxViewport || c.height > raster::kMaxViewport) {
        throw std::invalid_argument("image size must be within 1.." + std::to_string(raster::kMaxViewport));
    }
    if (!(c.fovyDeg > 0.0f && c.fovyDeg < 180.0f)) throw std::invalid_argument("--fovy must be in (0, 180) degrees");
    // The same rule as a scene file's camera (scene_file.cpp): the view matrix needs a frame.
    switch (viewFrameProblem(c)) {
        case ViewFrameProblem::EyeAtTarget: throw std::invalid_argument("the eye and the target must differ");
        case ViewFrameProblem::UpParallel:
            throw std::invalid_argument((std::ostringstream() << "--eye, --target: the viewing direction is parallel to the camera's up ("
                                         << c.up.x << ", " << c.up.y << ", " << c.up.z << "); look along another direction").str());
        case ViewFrameProblem::None: break;
    }
    if (o.lightPosition) {
        requireCoordinate(*o.lightPosition, "--light-pos");
        if (scene.lights.empty()) throw std::invalid_argument("--light-pos: the scene has no light");
        // A sun has a direction and no position: moving it would silently change nothing.
        if (scene.lights[0].type == LightType::Directional)
            throw std::invalid_argument("--light-pos: the scene's first light is directional, which has no position "
                                        "(its direction is set in the scene file)");
        scene.lights[0].position = *o.lightPosition;
    }
    if (o.lightRadius) applyLightRadius(scene, *o.lightRadius);
}

Frame renderFrame(const PreparedScene& prepared, const Technique& technique, const FrameSettings& settings) {
    const Scene& scene = prepared.scene();
    // A visibility technique shadows each light of the scene; a radiance technique lights the
    // scene itself (an environment map, and any lights the scene has), so it needs none.
    if (scene.lights.empty() && technique.output == TechniqueOutput::Visibility)
        throw std::invalid_argument("the scene has no light to cast shadows");
    const Light noLight{.intensity = glm::vec3(0.0f)};
    const TechniqueParams params(technique.name, technique.params, settings.params);
    Frame frame;
    frame.output = technique.output;
    frame.gbuffer = renderGBuffer(prepared.world(), scene.camera, settings.simd);
    const PreviousView* previous = settings.history ? settings.history->previousView() : nullptr;
    if (previous) frame.gbuffer.motion = surfaceMotion(frame.gbuffer, prepared.world(), scene, *previous);
    const CasterLevel casters = prepareCasters(prepared, params, frame.preparation);
    if (technique.prepare) {
        for (TechniqueStat& s : technique.prepare(prepared, casters.casters, params)) frame.preparation.push_back(std::move(s));
    }

    // Against simplified casters the technique sees each receiver lifted by its instance's
    // simplification error (liftedReceivers); the frame keeps and shades the G-buffer.
    const bool lift = !casters.instanceErrorM.empty();
    const GBuffer liftedGBuffer = lift ? liftedReceivers(frame.gbuffer, prepared.world(), casters.instanceErrorM) : GBuffer{};
    // A visibility technique runs once per light, in the scene's order; a radiance
    // technique once, with the first light (or none).
    const size_t passCount = technique.output == TechniqueOutput::Visibility ? scene.lights.size() : 1;
    for (size_t k = 0; k < passCount; ++k) {
        const Light& light = scene.lights.empty() ? noLight : scene.lights[k];
        frame.passes.push_back(runPass(technique,
                                       {.prepared = prepared,
                                        .gbuffer = lift ? liftedGBuffer : frame.gbuffer,
                                        .light = light,
                                        .simd = settings.simd,
                                        .params = params,
                                        .debugDir = passDebugDir(settings.debugDir, passCount, k),
                                        .progress = settings.progress,
                                        .casterScene = &casters.casters,
                                        .receiverLiftM = casters.instanceErrorM,
                                        .history = settings.history ? &settings.history->pass(prepared, technique,
                                                                                              settings.params, k)
                                                                    : nullptr,
                                        .frameIndex = settings.history ? settings.history->frames() : 0,
                                        .previous = previous},
                                       k, passCount));
        frame.techniqueMs += frame.passes.back().techniqueMs;
    }
    frame.shadow = framedOutputs(frame.passes);
    if (hasCasterLod(technique)) {
        frame.shadow.stats.push_back({"caster_lod_triangles", double(casters.casters.world().triangles.size())});
        frame.shadow.stats.push_back({"caster_lod_error_m", casters.errorM()});
    }
    if (technique.output == TechniqueOutput::Visibility) {
        frame.radiance = shadePasses(scene, frame.gbuffer, frame.passes);
    } else {
        if (frame.shadow.radiance.size() != frame.gbuffer.pixelCount())
            throw std::logic_error(technique.name + ": a radiance technique returned no radiance image");
        frame.radiance = frame.shadow.radiance;
    }
    if (settings.history) settings.history->endFrame(keepView(frame.gbuffer, scene));
    return frame;
}

}  // namespace shadowlab
