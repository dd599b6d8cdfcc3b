#include "shadows/environment/environment_source.h"

#include <numbers>
#include <stdexcept>

#include "shading/environment/environment_file.h"
#include "shading/environment/prefiltered_lobe.h"

namespace shadowlab {
namespace {

// The map as a type of its own, so that PreparedScene::derived keeps it apart from other
// environment maps a family might derive.
struct SceneEnvironmentMap {
    static constexpr DependsOn kDependsOn = DependsOn::FixedContent;
    EnvironmentMap map;
};

}  // namespace

const EnvironmentMap& sceneEnvironment(const PreparedScene& prepared, std::optional<double>* builtMs) {
    const Environment& environment = prepared.scene().environment;
    if (environment.map.empty())
        throw std::invalid_argument("the scene names no environment map (environment.map in the scene file)");
    const double rotation = double(environment.rotationDeg) * (std::numbers::pi / 180.0);
    return prepared
        .derived<SceneEnvironmentMap>([&] { return SceneEnvironmentMap{readEnvironmentMap(environment.map, rotation)}; },
                                      builtMs)
        .map;
}

// A material the tables serve: not Blinn-Phong (no lobe about a fixed direction), and a
// lobe the map resolves. The others are lit by the radiance cache, or refused by name.
bool tablesServe(const Material& m, const EnvironmentMap& map) {
    if (m.model == MaterialModel::BlinnPhong) return false;
    try {
        if (m.model == MaterialModel::Phong) checkLobe(GlossyLobe::NormalisedPhong, m.shininess, map);
        if (m.model == MaterialModel::Ggx) checkLobe(GlossyLobe::Ggx, m.roughness, map);
    } catch (const std::invalid_argument&) {
        return false;
    }
    return true;
}

namespace {

// Types of their own, so that PreparedScene::derived keeps them apart from any other
// family's tables or pyramid.
struct SceneLocalIllumination {
    static constexpr DependsOn kDependsOn = DependsOn::FixedContent;   // the map's and the materials'
    LocalIllumination tables;
};
struct ScenePyramid {
    static constexpr DependsOn kDependsOn = DependsOn::FixedContent;
    EnvironmentPyramid pyramid;
};

}  // namespace

const LocalIllumination& sceneLocalIllumination(const PreparedScene& prepared, std::optional<double>* builtMs) {
    const EnvironmentMap& map = sceneEnvironment(prepared);
    return prepared
        .derived<SceneLocalIllumination>(
            [&] {
                std::vector<Material> served;
                for (const Material& m : prepared.scene().materials) {
                    if (tablesServe(m, map)) served.push_back(m);
                }
                return SceneLocalIllumination{buildLocalIllumination(map, served)};
            },
            builtMs)
        .tables;
}

const EnvironmentPyramid& scenePyramid(const PreparedScene& prepared, std::optional<double>* builtMs) {
    const EnvironmentMap& map = sceneEnvironment(prepared);
    return prepared.derived<ScenePyramid>([&] { return ScenePyramid{buildPyramid(map)}; }, builtMs).pyramid;
}

std::vector<TechniqueStat> prepareEnvironment(const PreparedScene& prepared) {
    std::optional<double> ms;
    sceneEnvironment(prepared, &ms);
    if (ms) return {{"environment_ms", *ms}};
    return {};
}

}  // namespace shadowlab
