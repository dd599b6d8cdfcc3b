#include "scenes/camera_path.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "scenes/camera.h"
#include "scenes/error_text.h"
#include "scenes/instance_transform.h"
#include "scenes/scene_error.h"
#include "scenes/scene_file_parts.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

bool lightIsDirection(const std::vector<Light>& lights) {
    return !lights.empty() && lights.front().type == LightType::Directional;
}

const char* lightKey(const std::vector<Light>& lights) {
    return lightIsDirection(lights) ? "light_direction" : "light_position";
}

// Linear interpolation of two directions passes through zero if they are opposite; beyond
// this angle between two keyframes (170 degrees) the turn needs a keyframe in between.
constexpr float kMaxTurnCosine = -0.9848f;

// What is wrong with the last keyframe of `path`, given that the ones before it are right;
// "" if nothing.
std::string lastKeyframeProblem(const CameraPath& path, const std::vector<Light>& lights) {
    const PathKeyframe& key = path.keyframes.back();
    if (key.eye == key.target) return "the eye is on the target";
    if (key.light && lights.empty()) return "the scene has no light to move";
    if (key.light && lightIsDirection(lights) && *key.light == glm::vec3(0.0f)) return "the light's direction is zero";
    if (path.keyframes.size() == 1) return {};
    const PathKeyframe& previous = path.keyframes[path.keyframes.size() - 2];
    if (!(key.time > previous.time))
        return "times must increase from keyframe to keyframe, got " + std::to_string(key.time) + " after " +
               std::to_string(previous.time);
    // Frames are placed at fractions of the whole span, which must itself be a number.
    if (!std::isfinite(key.time - path.keyframes.front().time))
        return "the path's times span more than the largest number; use smaller times";
    if (key.light.has_value() != previous.light.has_value())
        return std::string("give ") + lightKey(lights) + " in every keyframe or in none";
    if (key.poses.size() != previous.poses.size()) return "give instances in every keyframe or in none";
    if (key.light && lightIsDirection(lights) &&
        glm::dot(glm::normalize(*key.light), glm::normalize(*previous.light)) < kMaxTurnCosine)
        return "the light turns by more than 170 degrees from the keyframe before; add a keyframe between";
    return {};
}

// In double, as (1 - s) a + s b: exact at both keys, and b - a cannot overflow.
glm::vec3 lerp(const glm::vec3& a, const glm::vec3& b, float s) {
    return glm::vec3((1.0 - double(s)) * glm::dvec3(a) + double(s) * glm::dvec3(b));
}

InstancePose lerp(const InstancePose& a, const InstancePose& b, float s) {
    return {lerp(a.translate, b.translate, s), lerp(a.rotateDeg, b.rotateDeg, s), lerp(a.scale, b.scale, s)};
}

// ---- Instances a keyframe moves ---------------------------------------------------------

// "instance": a name (one instance's alone) or an index into Scene::instances, of an
// instance that an "instances" entry made.
uint32_t instanceIndex(const JsonField& field, const Scene& scene, std::span<const PathInstance> parts) {
    uint32_t index = 0;
    if (field.raw().is_string()) {
        const std::string name = field.string();
        const auto named = [&](const MeshInstance& instance) { return instance.name == name; };
        const auto found = std::ranges::find_if(scene.instances, named);
        if (found == scene.instances.end()) field.fail("no instance is named " + inQuotes(name));
        if (std::ranges::count_if(scene.instances, named) > 1)
            field.fail("several instances are named " + inQuotes(name) + "; give its index");
        index = uint32_t(found - scene.instances.begin());
    } else {
        index = uint32_t(field.integer({0.0, double(scene.instances.size()) - 1.0, false, false}));
    }
    if (index >= parts.size())
        field.fail("instance " + inQuotes(scene.instances[index].name) +
                   " comes from a model; keyframes move the instances of \"instances\" entries");
    return index;
}

// A keyframe's "instances": each one's pose, in the order of path.instances, which the first
// keyframe to give them sets; every later one must give the same instances.
std::vector<InstancePose> readPoses(const JsonField& field, const Scene& scene, std::span<const PathInstance> parts,
                                    CameraPath& path) {
    const std::vector<JsonField> entries = field.elements();
    if (entries.empty()) field.fail("needs at least one instance");
    const bool first = path.instances.empty();
    std::vector<std::optional<InstancePose>> poses(first ? entries.size() : path.instances.size());
    for (size_t e = 0; e < entries.size(); ++e) {
        const JsonObject object = entries[e].object({"instance", "translate", "rotate", "scale", "matrix"});
        if (object.has("matrix"))
            object["matrix"].fail("a keyframe gives an instance translate, rotate and scale, which interpolate; "
                                  "a matrix does not");
        const uint32_t instance = instanceIndex(object["instance"], scene, parts);
        const std::string name = inQuotes(scene.instances[instance].name);
        const auto listed = std::ranges::find(path.instances, instance, &PathInstance::instance);
        if (first && listed != path.instances.end()) object["instance"].fail("lists instance " + name + " twice");
        if (!first && listed == path.instances.end())
            object["instance"].fail("instance " + name + " is not in the first keyframe's instances; every "
                                    "keyframe moves the same instances");
        if (first) path.instances.push_back(parts[instance]);
        std::optional<InstancePose>& pose = poses[first ? e : size_t(listed - path.instances.begin())];
        if (pose) object["instance"].fail("lists instance " + name + " twice");
        pose = readPose(object);
        MeshInstance placed = scene.instances[instance];
        placed.worldFromObject = posedWorldFromObject(parts[instance], *pose);
        checkInWorld(entries[e], placed, scene.meshes[placed.mesh]);
    }
    std::vector<InstancePose> ordered;
    for (size_t k = 0; k < poses.size(); ++k) {
        if (!poses[k])
            field.fail("misses instance " + inQuotes(scene.instances[path.instances[k].instance].name) +
                       ", which the first keyframe moves; every keyframe moves the same instances");
        ordered.push_back(*poses[k]);
    }
    return ordered;
}

// ---- CSV --------------------------------------------------------------------------------

std::vector<std::string> splitCommas(const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream in(line + ",");
    for (std::string field; std::getline(in, field, ',');) {
        const size_t first = field.find_first_not_of(" \t\r"), last = field.find_last_not_of(" \t\r");
        fields.push_back(first == std::string::npos ? "" : field.substr(first, last - first + 1));
    }
    return fields;
}

std::vector<std::string> csvColumns(const std::vector<Light>& lights, bool withLight) {
    std::vector<std::string> columns{"time", "eye_x", "eye_y", "eye_z", "target_x", "target_y", "target_z"};
    if (withLight)
        for (const char* axis : {"_x", "_y", "_z"}) columns.push_back(lightKey(lights) + std::string(axis));
    return columns;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ",") + name;
    return text;
}

// The whole field as a finite double, or nullopt.
std::optional<double> finiteNumber(const std::string& field) {
    double value = 0.0;
    const char* last = field.data() + field.size();
    const auto [end, error] = std::from_chars(field.data(), last, value);
    if (field.empty() || error != std::errc{} || end != last || !std::isfinite(value)) return std::nullopt;
    return value;
}

}  // namespace

PathSample samplePath(const CameraPath& path, int frame, int frames) {
    const std::vector<PathKeyframe>& keys = path.keyframes;
    const PathKeyframe& last = keys.back();
    const double t = frames == 1 ? keys.front().time
                   : frame == frames - 1 ? last.time
                                         : keys.front().time + (last.time - keys.front().time) * frame / (frames - 1);
    const auto placed = [&](const std::vector<InstancePose>& poses) {
        std::vector<InstancePlacement> placements;
        for (size_t i = 0; i < poses.size(); ++i)
            placements.push_back({path.instances[i].instance, posedWorldFromObject(path.instances[i], poses[i])});
        return placements;
    };
    if (t == last.time) return {t, last.eye, last.target, last.light, placed(last.poses)};
    // The segment [k, k + 1] with time k <= t < time k + 1: a keyframe's own time gives it exactly.
    const size_t k = size_t(std::ranges::upper_bound(keys, t, {}, &PathKeyframe::time) - keys.begin()) - 1;
    const float s = float((t - keys[k].time) / (keys[k + 1].time - keys[k].time));
    PathSample sample{t, lerp(keys[k].eye, keys[k + 1].eye, s), lerp(keys[k].target, keys[k + 1].target, s), {}, {}};
    if (keys[k].light) sample.light = lerp(*keys[k].light, *keys[k + 1].light, s);
    std::vector<InstancePose> poses;
    for (size_t i = 0; i < keys[k].poses.size(); ++i) poses.push_back(lerp(keys[k].poses[i], keys[k + 1].poses[i], s));
    sample.placements = placed(poses);
    return sample;
}

void placeOnPath(const PathSample& sample, int frame, Camera& camera, std::vector<Light>& lights) {
    camera.eye = sample.eye;
    camera.target = sample.target;
    if (viewFrameProblem(camera) != ViewFrameProblem::None)
        throw std::invalid_argument("frame " + std::to_string(frame) +
                                    " of the path: the camera's view is undefined there (its eye is on its target, "
                                    "or it looks straight along its up vector); add a keyframe");
    if (!sample.light) return;
    Light& light = lights.front();
    if (light.type == LightType::Directional) light.direction = glm::normalize(*sample.light);
    else light.position = *sample.light;
}

CameraPath readCameraPath(const JsonField& field, const Scene& scene, std::span<const PathInstance> parts) {
    const std::vector<Light>& lights = scene.lights;
    const JsonObject object = field.object({"frames", "keyframes"});
    CameraPath path;
    if (const auto frames = object.optional("frames"))
        path.frames = frames->integer({2.0, double(kMaxPathFrames), false, false});
    const std::vector<JsonField> keyframes = object["keyframes"].elements();
    if (keyframes.empty()) object["keyframes"].fail("needs at least one keyframe");
    if (keyframes.size() > kMaxPathKeyframes)
        object["keyframes"].fail("more than " + std::to_string(kMaxPathKeyframes) + " keyframes");
    for (const JsonField& entry : keyframes) {
        const JsonObject key = entry.object({"time", "eye", "target", lightKey(lights), "instances"});
        PathKeyframe& keyframe = path.keyframes.emplace_back();
        keyframe.time = key["time"].number();
        keyframe.eye = key["eye"].vec3(kCoordinate);
        keyframe.target = key["target"].vec3(kCoordinate);
        if (const auto light = key.optional(lightKey(lights))) keyframe.light = light->vec3(kCoordinate);
        if (const auto instances = key.optional("instances"))
            keyframe.poses = readPoses(*instances, scene, parts, path);
        if (const std::string problem = lastKeyframeProblem(path, lights); !problem.empty()) entry.fail(problem);
    }
    return path;
}

CameraPath parseCameraPathCsv(const std::string& text, const std::string& file, const std::vector<Light>& lights) {
    std::vector<std::string> columns;
    CameraPath path;
    int lineNumber = 0;
    const auto fail = [&](const std::string& problem) {
        throw SceneError(file + ": line " + std::to_string(lineNumber) + ": " + problem);
    };
    // Line by line in place: the text may be the largest a path file may be (kMaxPathFileBytes).
    for (size_t at = 0; at < text.size();) {
        const size_t end = std::min(text.find('\n', at), text.size());
        const std::string line = text.substr(at, end - at);
        at = end + 1;
        ++lineNumber;
        if (line.find_first_not_of(" \t\r") == std::string::npos || line.front() == '#') continue;
        const std::vector<std::string> fields = splitCommas(line);
        if (columns.empty()) {
            if (fields != csvColumns(lights, false) && fields != csvColumns(lights, true))
                fail("expected the header " + joined(csvColumns(lights, false)) + " (then " +
                     lightKey(lights) + "_x,_y,_z to move the first light), got " + line);
            columns = fields;
            continue;
        }
        if (fields.size() != columns.size())
            fail("expected " + std::to_string(columns.size()) + " values, got " + std::to_string(fields.size()));
        if (path.keyframes.size() == kMaxPathKeyframes)
            fail("more than " + std::to_string(kMaxPathKeyframes) + " keyframes");
        std::vector<float> values;
        for (size_t c = 0; c < fields.size(); ++c) {
            const std::optional<double> value = finiteNumber(fields[c]);
            if (!value) fail(columns[c] + ": expected a finite number, got '" + fields[c] + "'");
            if (c > 0 && !kCoordinate.contains(*value))
                fail(columns[c] + ": must be " + kCoordinate.describe() + " (metres), got '" + fields[c] + "'");
            values.push_back(float(*value));
            if (c == 0) path.keyframes.emplace_back().time = *value;
        }
        PathKeyframe& keyframe = path.keyframes.back();
        keyframe.eye = {values[1], values[2], values[3]};
        keyframe.target = {values[4], values[5], values[6]};
        if (values.size() == 10) keyframe.light = glm::vec3(values[7], values[8], values[9]);
        if (const std::string problem = lastKeyframeProblem(path, lights); !problem.empty()) fail(problem);
    }
    if (path.keyframes.empty()) fail(columns.empty() ? "no header and no keyframes" : "no keyframes after the header");
    return path;
}

}  // namespace shadowlab
