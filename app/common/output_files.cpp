#include "app/common/output_files.h"

#include <cstdint>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "scenes/write_file.h"

namespace shadowlab {

void requireOutputDirectories(std::initializer_list<const std::string*> paths) {
    for (const std::string* path : paths) {
        if (path->empty()) continue;
        const std::filesystem::path directory = std::filesystem::path(*path).parent_path();
        if (!std::filesystem::is_directory(directory.empty() ? "." : directory))
            throw std::runtime_error("cannot write '" + *path + "': no directory '" + directory.string() + "'");
        if (std::filesystem::is_directory(*path)) throw std::runtime_error("cannot write '" + *path + "': it is a directory");
    }
}

void writeCsvJsonSvg(const std::filesystem::path& stem, const std::string& csv, const std::string& json,
                     const std::string& svg) {
    for (const auto& [extension, text] : {std::pair{".csv", &csv}, {".json", &json}, {".svg", &svg}})
        writeTextFile(stem.string() + extension, *text);
}

void commitAndList(StagedOutputs& outputs) {
    for (const std::filesystem::path& file : outputs.commit())
        if (file.parent_path() == outputs.destination()) std::cout << "wrote " << file.string() << "\n";
}

std::string techniqueListStem(const std::vector<std::string>& techniques) {
    std::string joined;
    for (const std::string& t : techniques) joined += (joined.empty() ? "" : "+") + t;
    constexpr size_t kLongest = 96;
    if (joined.size() <= kLongest) return joined;
    uint64_t hash = 0xcbf29ce484222325ull;   // FNV-1a, 64 bits: the same name on every machine
    for (const unsigned char c : joined) hash = (hash ^ c) * 0x100000001b3ull;
    char tail[40];
    std::snprintf(tail, sizeof tail, "+%zu-more-%08x", techniques.size() - 1, unsigned(hash >> 32));
    return techniques.front() + tail;
}

}  // namespace shadowlab
