// `shadowlab export-obj`: every triangle of a scene in world space as OBJ.
#include <memory>
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

}  // namespace

void addExportObjCommand(CLI::App& command) {
    const auto args = std::make_shared<ExportArgs>();
    ExportArgs& a = *args;
    CLI::App* e = command.description("write every triangle of a scene in world space as OBJ");
    e->add_option("scene", a.scene, "built-in scene name or scene file")->required();
    e->add_option("out", a.path, "OBJ file to write")->required();
    e->callback([args] { writeObj(flatten(loadScene(args->scene)), args->path); });
}

}  // namespace shadowlab
