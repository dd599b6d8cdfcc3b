// Intermediate buffers a technique shows on request (`--debug-buffers DIR`): each is
// written as DIR/<technique>-<name>.exr (the exact float values, channel "Y") and
// DIR/<technique>-<name>.png (the values mapped linearly from [low, high] to black..white,
// for people). Row 0 is the top row, as for every image (conventions.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab {

class DebugBuffers {
public:
    // An empty directory writes nothing; otherwise it is created if missing.
    DebugBuffers(std::filesystem::path directory, std::string technique);

    bool enabled() const { return !directory_.empty(); }
    void write(const std::string& name, int width, int height, const std::vector<float>& values, float low,
               float high) const;

private:
    std::filesystem::path directory_;
    std::string technique_;
};

}  // namespace shadowlab
