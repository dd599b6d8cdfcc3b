// Helpers for scene tests: a private temporary directory and checks on SceneError texts.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "scenes/scene_error.h"

namespace shadowlab::test {

// A fresh directory under the system temp directory, removed with everything in it.
class TempDir {
public:
    TempDir() {
        std::random_device seed;
        path_ = std::filesystem::temp_directory_path() / ("shadowlab-scenes-" + std::to_string(seed()));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    // Writes bytes to name inside the directory and returns the full path.
    std::string write(const std::string& name, const std::string& bytes) const {
        const std::filesystem::path file = path_ / name;
        std::ofstream(file, std::ios::binary) << bytes;
        return file.string();
    }
    std::string path(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

// The message of the SceneError that action throws ("" and a failed check if none).
inline std::string sceneErrorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const SceneError& error) {
        return error.what();
    }
    FAIL_CHECK("expected a SceneError");
    return "";
}

// Checks that the message contains every expected piece (file name, field path, reason).
inline void checkMessage(const std::string& message, const std::vector<std::string>& pieces) {
    for (const std::string& piece : pieces) {
        INFO("message: ", message);
        CHECK_MESSAGE(message.find(piece) != std::string::npos, "missing \"", piece, "\"");
    }
}

}  // namespace shadowlab::test
