// Example 3: what there is to run. Lists the built-in scenes and every shadow technique with
// its parameters (name, default, meaning) and the reference it is scored against.
//
//   list_techniques [OUT.txt]
//
// prints the list, and also writes it to OUT.txt when given.
#include <cstdio>
#include <exception>
#include <string>

#include "frame/registry.h"
#include "scenes/scene_file.h"
#include "scenes/write_file.h"
#include "shading/image_io.h"
#include "shadows/technique.h"

using namespace shadowlab;

int main(int argc, char** argv) try {
    std::string text = "built-in scenes in " + builtinSceneDir() + ":\n ";
    for (const std::string& name : builtinSceneNames()) text += " " + name;
    text += "\n\ntechniques:\n";
    // The registry (shadows/technique.h): each technique is a name, a description, its
    // parameters with defaults, and a function from the G-buffer and the light to V.
    for (const Technique& technique : techniques()) {
        text += technique.name + " (scored against " + technique.referenceName + ")\n    " + technique.description + "\n";
        for (const ParamSpec& param : technique.params)
            text += "    " + param.name + "=" + param.defaultValue + "  " + paramHelp(param) + "\n";
    }
    std::fputs(text.c_str(), stdout);
    if (argc > 1) writeTextFile(argv[1], text);   // whole or not at all (shading/image_io.h)
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "list_techniques: %s\n", e.what());
    return 1;
}
