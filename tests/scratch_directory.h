// A fresh, empty directory for one test, removed with everything in it afterwards.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

namespace shadowlab::test {

struct ScratchDirectory {
    std::filesystem::path path;

    explicit ScratchDirectory(const std::string& name)
        : path(std::filesystem::temp_directory_path() / ("shadowlab_test_" + std::to_string(::getpid()) + "_" + name)) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~ScratchDirectory() { std::filesystem::remove_all(path); }

    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(path)) names.push_back(e.path().filename().string());
        return names;
    }
};

}  // namespace shadowlab::test
