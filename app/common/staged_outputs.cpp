#include "app/common/staged_outputs.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <stdlib.h>

#include "scenes/error_text.h"

namespace shadowlab {
namespace fs = std::filesystem;
namespace {

std::string named(const fs::path& path) {
    std::string text(1, '\'');   // appended, not chained: GCC 12 warns wrongly of a chain of string +
    text += oneLine(path.string());
    text += '\'';
    return text;
}

// What stands in the way of writing a file at `to` (relative parts under `root`), or "".
std::string obstacle(const fs::path& root, const fs::path& relative) {
    fs::path at = root;
    for (auto part = relative.begin(); part != relative.end(); ++part) {
        at /= *part;
        std::error_code error;
        const fs::file_type type = fs::status(at, error).type();
        const bool last = std::next(part) == relative.end();
        if (last && type == fs::file_type::directory) return "cannot write " + named(at) + ": a folder is in the way";
        if (!last && type != fs::file_type::not_found && type != fs::file_type::directory)
            return "cannot write " + named(root / relative) + ": " + named(at) + " is not a folder";
    }
    return {};
}

}  // namespace

StagedOutputs::StagedOutputs(const fs::path& destination, const std::vector<std::string>& planned)
    : destination_(destination.empty() ? fs::path(".") : destination) {
    for (const std::string& name : planned)
        if (const std::string problem = obstacle(destination_, name); !problem.empty()) throw std::runtime_error(problem);
    fs::path at;
    for (const fs::path& part : destination_) {   // the folders to make, outermost first
        at /= part;
        std::error_code error;
        if (fs::exists(at, error)) continue;
        if (!fs::create_directory(at, error) && error)
            throw std::runtime_error("cannot make the folder " + named(at) + ": " + error.message());
        made_.push_back(at);
    }
    if (!fs::is_directory(destination_))
        throw std::runtime_error("cannot write into " + named(destination_) + ": not a folder");
    // A short name (mkdtemp's six letters): a file's name within it is as long as the user's.
    std::string pattern = (destination_ / ".sl-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
        throw std::runtime_error("cannot write into " + named(destination_) + ": " + std::strerror(errno));
    staging_ = pattern;
}

StagedOutputs::~StagedOutputs() {
    std::error_code ignored;   // best effort: the command's own error is what the user needs
    fs::remove_all(staging_, ignored);
    if (committed_) return;
    for (auto folder = made_.rbegin(); folder != made_.rend(); ++folder) fs::remove(*folder, ignored);   // if empty
}

std::vector<fs::path> StagedOutputs::commit() {
    std::vector<fs::path> staged;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(staging_))
        if (!entry.is_directory()) staged.push_back(fs::relative(entry.path(), staging_));
    std::ranges::sort(staged);
    for (const fs::path& relative : staged)
        if (const std::string problem = obstacle(destination_, relative); !problem.empty()) throw std::runtime_error(problem);
    std::vector<fs::path> written;
    for (const fs::path& relative : staged) {
        const fs::path to = destination_ / relative;
        fs::create_directories(to.parent_path());
        fs::rename(staging_ / relative, to);
        written.push_back(to);
    }
    committed_ = true;
    return written;
}

}  // namespace shadowlab
