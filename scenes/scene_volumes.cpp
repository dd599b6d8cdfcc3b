// The "volumes" array of a scene file: procedural density volumes (scene.h, DensityVolume).
#include <array>

#include "scenes/procedural_casters.h"
#include "scenes/scene_file_parts.h"

namespace shadowlab {
namespace {

enum class VolumeKind { Constant, SmokePuff };
constexpr std::array<std::pair<std::string_view, VolumeKind>, 2> kVolumeKinds{{
    {"constant", VolumeKind::Constant}, {"smoke-puff", VolumeKind::SmokePuff}}};
// 256^3 voxels are 64 MiB of floats: past that a scene file would ask for the machine.
constexpr Interval kVoxelsPerAxis{1.0, 256.0, false, false};

}  // namespace

DensityVolume readVolume(const JsonField& field, uint64_t& voxels) {
    const JsonObject object = field.object();
    const VolumeKind kind = object["procedural"].choice(kVolumeKinds);
    if (kind == VolumeKind::Constant) object.allowOnly({"name", "procedural", "min", "max", "density"});
    else object.allowOnly({"name", "procedural", "min", "max", "density", "resolution", "seed"});
    const glm::vec3 min = object["min"].vec3(kCoordinate), max = object["max"].vec3(kCoordinate);
    if (!glm::all(glm::lessThan(min, max))) object["max"].fail("must be greater than min in x, y and z");
    const float density = object["density"].number(kNonNegative);
    const int resolution = kind == VolumeKind::Constant ? 1 : object["resolution"].integer(kVoxelsPerAxis);
    // Counted before the voxels are made: a 256^3 puff took 1.8 s to be refused.
    voxels += uint64_t(resolution) * uint64_t(resolution) * uint64_t(resolution);
    if (voxels > kMaxSceneVoxels)
        field.fail("the volumes hold more than " + std::to_string(kMaxSceneVoxels) + " voxels together");
    DensityVolume volume = kind == VolumeKind::Constant
                               ? makeConstantVolume(min, max, density)
                               : makeSmokePuff(min, max, resolution, density,
                                               object.has("seed") ? uint64_t(object["seed"].integer(kSeed)) : 1);
    volume.name = object["name"].string();
    return volume;
}

}  // namespace shadowlab
