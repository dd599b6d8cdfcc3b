#include "shadows/reference/scene_rays.h"

#include <memory>
#include <utility>

#include "shadows/caster_transmission.h"

namespace shadowlab {
namespace {

// What the scene keeps: the transmission the BVH's filter reads in place, and the BVH.
struct SceneRays {
    static constexpr DependsOn kDependsOn = DependsOn::WorldGeometry;
    std::unique_ptr<const CasterTransmission> transmission;
    std::unique_ptr<const ReferenceVisibility> rays;
};

}  // namespace

const ReferenceVisibility& sceneRays(const PreparedScene& casters, std::optional<double>* builtMs) {
    const SceneRays& kept = casters.derived<SceneRays>(
        [&casters] {
            auto transmission = std::make_unique<const CasterTransmission>(casters.scene(), casters.world());
            auto rays = std::make_unique<const ReferenceVisibility>(casters.world(), transmission.get());
            return SceneRays{std::move(transmission), std::move(rays)};
        },
        builtMs);
    return *kept.rays;
}

}  // namespace shadowlab
