// `shadowlab techniques`: every shadow technique of the registry with its parameters.
#include <cstdio>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "frame/registry.h"
#include "shadows/technique_params.h"

namespace shadowlab {
namespace {

void printTechniques() {
    for (const Technique& tech : techniques()) {
        std::printf("%-16s %s\n", tech.name.c_str(), tech.description.c_str());
        for (const ParamSpec& p : tech.params)
            std::printf("    %s=%s  %s\n", p.name.c_str(), p.defaultValue.c_str(), paramHelp(p).c_str());
    }
}

}  // namespace

void addTechniquesCommand(CLI::App& command) {
    command.description("list the shadow techniques and their parameters")->callback(printTechniques);
}

}  // namespace shadowlab
