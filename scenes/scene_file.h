// Loading scenes from JSON files (docs/scene-format.md) and naming the built-in ones.
#pragma once

#include <string>
#include <vector>

#include "scenes/scene.h"
#include "scenes/scene_error.h"

namespace shadowlab {

// nameOrPath is a path when it ends in ".json", ".gltf" or ".glb" or contains a '/',
// otherwise the stem of a scene file in sceneDir. A .gltf or .glb file is read as a glTF
// scene (scenes/gltf_scene.h), anything else as a scene file. Throws SceneError for every invalid or unreadable input.
Scene loadScene(const std::string& nameOrPath, const std::string& sceneDir);
// That rule: whether loadScene reads nameOrPath as a path rather than a built-in scene's name.
bool looksLikePath(const std::string& nameOrPath);

// A scene file's text already in memory; `path` names it in errors, and the meshes it names
// are found relative to its directory.
Scene parseScene(const std::string& text, const std::string& path);

// Stems of the *.json files in sceneDir, sorted (none if it cannot be read).
std::vector<std::string> sceneNamesIn(const std::string& sceneDir);

// The data folder (scene files in scenes/, and meshes/, environments/, photos/, textures/)
// of a program compiled with `compiledDir`: the installed data beside the running
// executable, <its dir>/../share/shadowlab, if that directory exists (an installed
// `shadowlab`, wherever its prefix is moved); otherwise compiledDir.
std::string findBuiltinDataDir(const std::string& compiledDir);

// The built-in scene directory, the first of (docs/scene-format.md, "Finding scenes"):
//   $SHADOWLAB_SCENE_DIR, if set and not empty;
//   scenes/ in findBuiltinDataDir(compiledDataDir).
std::string findBuiltinSceneDir(const std::string& compiledDataDir);

// The same for the calling program. SHADOWLAB_DATA_DIR is a compile definition of the
// CMake target shadowlab::scenes for the programs that link it (not for the library's own
// sources): the source tree's assets/ in the build tree, <prefix>/share/shadowlab against
// an installed package. These are static so that each translation unit expands the
// definition it was compiled with; no installed library calls them.
#ifdef SHADOWLAB_DATA_DIR
static inline std::string builtinDataDir() { return findBuiltinDataDir(SHADOWLAB_DATA_DIR); }

static inline std::string builtinSceneDir() { return findBuiltinSceneDir(SHADOWLAB_DATA_DIR); }

// Stems of the *.json files in the built-in scene directory, sorted.
static inline std::vector<std::string> builtinSceneNames() { return sceneNamesIn(builtinSceneDir()); }

// A scene file path, or the name of a built-in scene.
static inline Scene loadScene(const std::string& nameOrPath) { return loadScene(nameOrPath, builtinSceneDir()); }
#endif

}  // namespace shadowlab
