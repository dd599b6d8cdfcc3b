// `shadowlab export-obj`: every triangle of a scene in world space as OBJ.
#include <string>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "scenes/obj_writer.h"
#include "scenes/scene_file.h"

namespace shadowlab {
namespace {

struct ExportArgs {
    std::string scene, path;
};

void runExportObj(const ExportArgs& a) { writeObj(flatten(loadScene(a.scene)), a.path); }

}  // namespace

void addExportObjCommand(CLI::App& command) {
    ExportArgs& a = argumentsRunBy<ExportArgs>(command, runExportObj);
    CLI::App* e = command.description("write every triangle of a scene in world space as OBJ");
    e->add_option("scene", a.scene, "built-in scene name or scene file")->required();
    e->add_option("out", a.path, "OBJ file to write")->required();
}

}  // namespace shadowlab
