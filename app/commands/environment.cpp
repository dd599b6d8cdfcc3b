// `shadowlab environment MAP`: reads an environment map as the techniques would, and writes
// its intermediate buffers (docs/environment-lighting.md): the map, its nine-coefficient
// spherical-harmonic reconstruction, the irradiance of a white Lambert surface facing each
// direction, the median-cut and structured-importance lights drawn on the map and, on request, prefiltered maps for
// Phong and GGX lobes (with GGX, the split-sum scale and bias table), with the figures printed.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/commands/commands.h"
#include "app/common/staged_outputs.h"
#include "raster/portable_constants.h"
#include "scenes/write_file.h"
#include "shading/environment/environment_debug.h"
#include "shading/environment/environment_file.h"
#include "shading/environment/prefiltered_lobe.h"
#include "shading/environment/split_sum_table.h"
#include "shading/environment/structured_sampling.h"
#include "shading/image_io.h"

namespace shadowlab {
namespace {

struct EnvironmentArgs {
    std::string map, outDir = "out/environment";
    double rotationDegrees = 0.0, shWindow = 0.0;
    int lights = 16;
    std::vector<double> phongShininess, ggxRoughness;   // a prefiltered map for each
    float exposure = 0.0f;
};

void writeImage(const std::filesystem::path& dir, const std::string& name, int width, int height,
                const std::vector<glm::vec3>& radiance, const ToneMapOptions& tone) {
    ImageChannels image;
    image.width = width, image.height = height;
    setRadiance(image, radiance);
    writeExr(dir / (name + ".exr"), image);
    writePng(dir / (name + ".png"), width, height, toSrgb8Image(radiance, tone));
}

void writeImage(const std::filesystem::path& dir, const std::string& name, const EnvironmentMap& map,
                const std::vector<glm::vec3>& radiance, const ToneMapOptions& tone) {
    writeImage(dir, name, map.width, map.height, radiance, tone);
}

// The GGX split-sum table as an image: A in red, B in green, n . v growing to the right and
// alpha downwards, one texel per entry, unscaled (both lie in [0, 1]).
void writeSplitSum(const std::filesystem::path& dir) {
    const SplitSumTable table = buildSplitSumTable();
    std::vector<glm::vec3> texels(table.scale.size());
    for (size_t k = 0; k < texels.size(); ++k) texels[k] = glm::vec3(table.scale[k], table.bias[k], 0.0f);
    writeImage(dir, "split-sum", table.size, table.size, texels, ToneMapOptions{0.0f, ToneOperator::Clamp});
}

nlohmann::ordered_json lightsJson(const std::vector<EnvironmentLight>& lights) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const EnvironmentLight& l : lights) {
        rows.push_back({{"direction", {l.direction.x, l.direction.y, l.direction.z}},
                        {"power", {l.power.r, l.power.g, l.power.b}},
                        {"solid_angle", l.solidAngle},
                        {"texels_first", {l.first.x, l.first.y}},
                        {"texels_last", {l.last.x, l.last.y}}});
    }
    return rows;
}

// The prefiltered map of each requested lobe, as `prefiltered-phong-40` or `prefiltered-ggx-0.25`.
void writePrefiltered(const std::filesystem::path& dir, const EnvironmentMap& map, const EnvironmentPyramid& pyramid,
                      GlossyLobe lobe, const std::vector<double>& parameters, const ToneMapOptions& tone) {
    for (double parameter : parameters) {
        const EnvironmentMap prefiltered = prefilterLobe(map, pyramid, lobe, parameter);
        std::ostringstream name;
        name << (lobe == GlossyLobe::NormalisedPhong ? "prefiltered-phong-" : "prefiltered-ggx-") << parameter;
        writeImage(dir, name.str(), prefiltered, prefiltered.radiance, tone);
    }
}

void runEnvironmentCommand(const EnvironmentArgs& a) {
    checkShWindow(a.shWindow);   // before the work of reading the map
    const EnvironmentMap map = readEnvironmentMap(a.map, a.rotationDegrees * kPi / 180.0);
    const ShCoefficients radiance = projectRadiance(map);
    const ShCoefficients irradiance = irradianceOf(radiance, a.shWindow);
    const std::vector<EnvironmentLight> lights = medianCutLights(map, a.lights);
    const EnvironmentPyramid pyramid = buildPyramid(map);
    std::vector<uint32_t> structuredRegions;
    const std::vector<EnvironmentLight> structured = structuredLights(map, pyramid, a.lights, &structuredRegions);
    for (double n : a.phongShininess) checkLobe(GlossyLobe::NormalisedPhong, n, map);   // before any output
    for (double alpha : a.ggxRoughness) checkLobe(GlossyLobe::Ggx, alpha, map);
    StagedOutputs outputs(a.outDir, {"environment.json"});
    const std::filesystem::path& dir = outputs.folder();
    const ToneMapOptions tone{a.exposure, ToneOperator::Reinhard};
    writeImage(dir, "environment", map, map.radiance, tone);
    writeImage(dir, "sh-radiance", map, shImage(map, radiance), tone);
    writeImage(dir, "sh-irradiance", map, shImage(map, irradiance, 1.0 / kPi), tone);
    writePng(dir / "lights.png", map.width, map.height, lightsImage(map, lights, medianCutRegions(map, lights), tone));
    writePng(dir / "structured-lights.png", map.width, map.height, lightsImage(map, structured, structuredRegions, tone));
    writePrefiltered(dir, map, pyramid, GlossyLobe::NormalisedPhong, a.phongShininess, tone);
    writePrefiltered(dir, map, pyramid, GlossyLobe::Ggx, a.ggxRoughness, tone);
    if (!a.ggxRoughness.empty()) writeSplitSum(dir);
    const glm::dvec3 power = environmentPower(map);
    nlohmann::ordered_json json = {{"map", map.source},
                                   {"width", map.width},
                                   {"height", map.height},
                                   {"rotation_degrees", a.rotationDegrees},
                                   {"power", {power.r, power.g, power.b}},
                                   {"sh_radiance", nlohmann::ordered_json::array()},
                                   {"lights", lightsJson(lights)},
                                   {"structured_lights", lightsJson(structured)}};
    for (const glm::dvec3& c : radiance.c) json["sh_radiance"].push_back({c.r, c.g, c.b});
    writeTextFile(dir / "environment.json", json.dump(2) + "\n");
    outputs.commit();
    std::printf("%s: %d x %d texels, integral of L dOmega (%.6g, %.6g, %.6g)\n", map.source.c_str(), map.width, map.height,
                power.r, power.g, power.b);
    std::printf("L_00 (%.6g, %.6g, %.6g); %d median-cut and structured lights; buffers in %s\n", radiance.c[0].r, radiance.c[0].g,
                radiance.c[0].b, a.lights, outputs.destination().c_str());
}

}  // namespace

void addEnvironmentCommand(CLI::App& command) {
    EnvironmentArgs& a = argumentsRunBy<EnvironmentArgs>(command, runEnvironmentCommand);
    CLI::App* e = command.description("an environment map's buffers: SH reconstruction and irradiance, median-cut lights, prefiltered lobes");
    e->add_option("map", a.map, "latitude-longitude map (.exr or .hdr)")->required()->check(CLI::ExistingFile);
    e->add_option("--rotation", a.rotationDegrees, "turn about +Y, degrees (right-handed)")->capture_default_str()->check(CLI::Range(-3600.0, 3600.0));
    e->add_option("--lights", a.lights, "median-cut lights to draw")->capture_default_str()->check(CLI::Range(1, 1 << 20));
    e->add_option("--phong", a.phongShininess, "write the map prefiltered for normalised Phong of this shininess (repeatable)");
    e->add_option("--ggx", a.ggxRoughness, "write the map prefiltered for GGX of this roughness (repeatable), and the split-sum table");
    e->add_option("--sh-window", a.shWindow, "sinc^4 window width against ringing (0: off, else > 2)")->capture_default_str();
    e->add_option("--exposure", a.exposure, "stops for the PNGs")->capture_default_str()->check(CLI::Range(-30.0f, 30.0f));
    e->add_option("--out", a.outDir, "directory for the EXR, PNG and JSON files")->capture_default_str();
}

}  // namespace shadowlab
