#include "shadows/environment/unshadowed_light.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "scenes/error_text.h"
#include "shading/environment/radiance_cache.h"
#include "shading/surface_albedo.h"
#include "shadows/environment/environment_source.h"

namespace shadowlab {

const SettingsTable<UnshadowedSettings>& unshadowedSettingsTable() {
    using S = UnshadowedSettings;
    static const auto table =
        SettingsTable<S>()
            .choice("unshadowed", member(&S::method),
                    {{"tables", UnshadowedMethod::Tables, "SH irradiance and prefiltered lobes (Lambert, Phong, GGX)"},
                     {"radiance-cache", UnshadowedMethod::RadianceCache,
                      "a table over normals per material and frame, any BRDF"}},
                    "how C, the unshadowed light, is computed")
            .integer("cache-size", member(&S::cacheSize), 2, 1024, "radiance-cache: texels a side of each material's table");
    return table;
}

std::vector<TechniqueStat> prepareUnshadowedLight(const PreparedScene& prepared, const UnshadowedSettings& settings) {
    if (settings.method != UnshadowedMethod::Tables) return {};
    std::optional<double> ms;
    sceneLocalIllumination(prepared, &ms);
    if (ms) return {{"local_illumination_ms", *ms}};
    return {};
}

namespace {

std::vector<bool> visibleMaterials(const GBuffer& g, size_t count) {
    std::vector<bool> visible(count, false);
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (g.hit[k]) visible.at(g.material[k]) = true;
    }
    return visible;
}

// Per pixel, C from `at(pixel, N, wo)`; Lookup is compiled in.
template <class Lookup>
std::vector<glm::vec3> perPixel(const ShadowInputs& in, const Lookup& at) {
    const GBuffer& g = in.gbuffer;
    const glm::dvec3 eye(in.camera().eye);
    std::vector<glm::vec3> C(g.pixelCount(), glm::vec3(0.0f));
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.pixelCount()), [&](const tbb::blocked_range<size_t>& pixels) {
        for (size_t k = pixels.begin(); k != pixels.end(); ++k) {
            if (!g.hit[k]) continue;
            const glm::dvec3 wo = glm::normalize(eye - glm::dvec3(g.position[k]));
            C[k] = glm::vec3(at(k, glm::dvec3(g.shadingNormal[k]), wo));
        }
    });
    return C;
}

}  // namespace

void refuseUnservedMaterials(const ShadowInputs& in, const UnshadowedSettings& settings) {
    const std::vector<Material>& materials = in.scene().materials;
    const std::vector<bool> visible = visibleMaterials(in.gbuffer, materials.size());
    if (settings.method == UnshadowedMethod::RadianceCache) {
        for (size_t m = 0; m < materials.size(); ++m) {
            if (visible[m] && materials[m].textured())
                throw std::invalid_argument("material " + inQuotes(materials[m].name) +
                                            ": the radiance cache holds one albedo per material, and this one has an "
                                            "albedo texture; use --param unshadowed=tables");
        }
        return;
    }
    const EnvironmentMap& map = sceneEnvironment(in.prepared);
    for (size_t m = 0; m < materials.size(); ++m) {
        if (visible[m] && !tablesServe(materials[m], map))
            throw std::invalid_argument("material " + inQuotes(materials[m].name) +
                                        ": prefiltered tables cannot light it (Blinn-Phong, or a lobe too sharp "
                                        "for the map); use --param unshadowed=radiance-cache");
    }
}

std::vector<glm::vec3> unshadowedLight(const ShadowInputs& in, const UnshadowedSettings& settings,
                                       std::vector<TechniqueStat>& stats) {
    const std::vector<Material>& materials = in.scene().materials;
    const GBuffer& g = in.gbuffer;
    if (settings.method == UnshadowedMethod::Tables) {
        const LocalIllumination& local = sceneLocalIllumination(in.prepared);
        const std::vector<AlbedoTexture>& textures = in.scene().albedoTextures;
        return perPixel(in, [&](size_t k, const glm::dvec3& N, const glm::dvec3& wo) {
            const Material& material = materials[g.material[k]];
            return unshadowedRadiance(local, material, surfaceAlbedo(material, textures, g, k), N, wo);
        });
    }
    const EnvironmentMap& map = sceneEnvironment(in.prepared);
    const std::vector<bool> visible = visibleMaterials(in.gbuffer, materials.size());
    const Camera& camera = in.camera();
    const glm::dvec3 toViewer = glm::normalize(glm::dvec3(camera.eye) - glm::dvec3(camera.target));
    std::vector<RadianceCache> caches(materials.size());
    for (size_t m = 0; m < materials.size(); ++m) {
        if (visible[m]) caches[m] = buildRadianceCache(map, scenePyramid(in.prepared), materials[m], toViewer, settings.cacheSize);
    }
    stats.push_back({"radiance_caches_count", double(std::count(visible.begin(), visible.end(), true))});
    return perPixel(in, [&](size_t k, const glm::dvec3& N, const glm::dvec3&) { return lookupRadianceCache(caches[g.material[k]], N); });
}

}  // namespace shadowlab
