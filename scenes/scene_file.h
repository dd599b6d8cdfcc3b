// Loading scenes from JSON files (docs/scene-format.md) and naming the built-in ones.
#pragma once

#include <string>
#include <vector>

#include "scenes/scene.h"
#include "scenes/scene_error.h"

namespace shadowlab {

// nameOrPath is a path when it ends in ".json" or contains a '/', otherwise the stem of a
// scene file in sceneDir. Throws SceneError for every invalid or unreadable input.
Scene loadScene(const std::string& nameOrPath, const std::string& sceneDir);

// A scene file's text already in memory; `path` names it in errors, and the meshes it names
// are found relative to its directory.
Scene parseScene(const std::string& text, const std::string& path);

// Stems of the *.json files in sceneDir, sorted (none if it cannot be read).
std::vector<std::string> sceneNamesIn(const std::string& sceneDir);

// The built-in scene directory of a program compiled with `compiledDir`, the first of
// (docs/scene-format.md, "Finding scenes"):
//   $SHADOWLAB_SCENE_DIR, if set and not empty;
//   the installed data beside the running executable, <its dir>/../share/shadowlab/scenes,
//     if that directory exists (an installed `shadowlab`, wherever its prefix is moved);
//   compiledDir.
std::string findBuiltinSceneDir(const std::string& compiledDir);

// The same for the calling program. SHADOWLAB_SCENE_DIR is a compile definition of the
// CMake target shadowlab::scenes for the programs that link it (not for the library's own
// sources): the source tree's scenes/ in the build tree, <prefix>/share/shadowlab/scenes
// against an installed package. These are static so that each translation unit expands
// the definition it was compiled with; no installed library calls them.
#ifdef SHADOWLAB_SCENE_DIR
static inline std::string builtinSceneDir() { return findBuiltinSceneDir(SHADOWLAB_SCENE_DIR); }

// Stems of the *.json files in the built-in scene directory, sorted.
static inline std::vector<std::string> builtinSceneNames() { return sceneNamesIn(builtinSceneDir()); }

// A scene file path, or the name of a built-in scene.
static inline Scene loadScene(const std::string& nameOrPath) { return loadScene(nameOrPath, builtinSceneDir()); }
#endif

}  // namespace shadowlab
