// A command's output files, whole or not at all (docs/reliability.md, "Reliability"). The command writes
// every file into a staging folder inside its destination folder (so on the same file
// system); commit() checks every destination first (no folder where a file goes, no file
// where a folder must be), then moves each file into place with rename(), which is atomic.
// If the command throws before commit(), or a check fails, the staging folder goes with
// everything in it, and so do the folders this made: nothing of the failed run is left.
// Shards writing into one folder each stage apart, so one's failure removes none of the
// others' files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab {

class StagedOutputs {
public:
    // Makes `destination` (and its parents) if missing and a staging folder in it, so that
    // a destination that cannot be written fails before the work. `planned`: names the
    // command will write, relative to `destination`, known before the work and checked now.
    explicit StagedOutputs(const std::filesystem::path& destination, const std::vector<std::string>& planned = {});
    ~StagedOutputs();
    StagedOutputs(const StagedOutputs&) = delete;
    StagedOutputs& operator=(const StagedOutputs&) = delete;

    // Where the command writes: files named as they are to be named under the destination.
    const std::filesystem::path& folder() const { return staging_; }
    const std::filesystem::path& destination() const { return destination_; }

    // Moves every staged file into the destination; returns their destination paths,
    // sorted. Throws std::runtime_error, having moved nothing, if a destination is taken by
    // a folder or a parent of one by a file.
    std::vector<std::filesystem::path> commit();

private:
    std::filesystem::path destination_, staging_;
    std::vector<std::filesystem::path> made_;   // folders this made, outermost first
    bool committed_ = false;
};

}  // namespace shadowlab
