// The one error type of every reader below the scene loader (meshes, images, paths, JSON
// fields, files), at the bottom of scenes/ so that none of them includes the loader for it.
#pragma once

#include <stdexcept>

namespace shadowlab {

// Any problem with a scene or mesh file. The message always starts with the file and,
// inside a JSON file, the path of the offending field, so that it can be fixed without
// a debugger: "scenes/x.json: lights[0].radius: must be > 0, got -1".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A file the user named that does not exist (regularFileSize, read_file.h): a SceneError whose
// type says so, for a caller that tells it apart (the Python module's FileNotFoundError).
class MissingFileError : public SceneError {
public:
    using SceneError::SceneError;
};

}  // namespace shadowlab
