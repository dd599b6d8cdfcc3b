#include "app/commands/options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include <unistd.h>

#include "app/measure/sweep.h"
#include "raster/fixed_point.h"

namespace shadowlab {
namespace {

// "x,y,z" -> vec3; CLI11 reports the message on failure.
std::string parseVec3(const std::string& text, glm::vec3& out) {
    std::istringstream in(text);
    char comma1 = 0, comma2 = 0;
    if (!(in >> out.x >> comma1 >> out.y >> comma2 >> out.z) || comma1 != ',' || comma2 != ',' || !in.eof()) {
        return "expected three numbers as x,y,z, got '" + text + "'";
    }
    if (!std::isfinite(out.x) || !std::isfinite(out.y) || !std::isfinite(out.z)) return "values must be finite";
    return {};
}

}  // namespace

void addVec3Option(CLI::App* cmd, const std::string& name, std::optional<glm::vec3>& target, const std::string& help) {
    cmd->add_option_function<std::string>(name, [&target, name](const std::string& text) {
        glm::vec3 v;
        if (const std::string error = parseVec3(text, v); !error.empty()) throw CLI::ValidationError(name, error);
        target = v;
    }, help)->type_name("X,Y,Z");
}

void addOptionalText(CLI::App* cmd, const std::string& name, std::optional<std::string>& target, const std::string& help) {
    cmd->add_option_function<std::string>(name, [&target](const std::string& text) { target = text; }, help)->type_name("TEXT");
}

void addSizeOptions(CLI::App* cmd, SceneOverrides& overrides) {
    cmd->add_option("--width", overrides.width, "image width in pixels")->check(CLI::Range(1, raster::kMaxViewport));
    cmd->add_option("--height", overrides.height, "image height in pixels")->check(CLI::Range(1, raster::kMaxViewport));
}

void addLightSelection(CLI::App* cmd, SceneOverrides& overrides) {
    cmd->add_option("--light", overrides.light,
                    "shadow and shade only the scene's light N (0: the first); default: every light of the scene")
        ->type_name("N");
}

void addLightOptions(CLI::App* cmd, SceneOverrides& overrides) {
    addLightSelection(cmd, overrides);
    addVec3Option(cmd, "--light-pos", overrides.lightPosition, "position (centre) of the scene's first light (the --light one)");
    cmd->add_option("--light-radius", overrides.lightRadius,
                    "radius of the scene's first light (the --light one), which must be a disk (m, > 0)");
}

void addSimdOption(CLI::App* cmd, std::string& simd) {
    cmd->add_option("--simd", simd, "scalar, avx2, avx512 or auto")->capture_default_str();
}

void addProgressFlag(CLI::App* cmd, bool& progress) {
    cmd->add_flag("--progress", progress,
                  "draw the progress line on stderr even if it is not a terminal (on a terminal it is drawn anyway, for work over 2 s)");
}

void addTimingOptions(CLI::App* cmd, const std::string& unit, int& runs, int& warmupRuns, std::string& simd) {
    cmd->add_option("--runs", runs, "measured " + unit)->capture_default_str()->check(CLI::Range(1, kMaxRuns));
    cmd->add_option("--warmup", warmupRuns, "warm-up " + unit)->capture_default_str()->check(CLI::Range(0, kMaxWarmupRuns));
    addSimdOption(cmd, simd);
}

void requireFiniteFloats(CLI::App& app) {
    const CLI::Validator finite(
        [](std::string& text) -> std::string {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !std::isfinite(value)) return "must be a finite number, got '" + text + "'";
            return {};
        },
        "", "FINITE");
    for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
        for (CLI::Option* option : command->get_options()) {
            if (option->get_type_name().find("FLOAT") != std::string::npos) option->check(finite);
        }
    }
}

Progress* progressIfWanted(Progress& progress, bool asked) {
    return asked || isatty(fileno(stderr)) ? &progress : nullptr;
}

}  // namespace shadowlab
