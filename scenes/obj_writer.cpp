#include "scenes/obj_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "scenes/write_file.h"

namespace shadowlab {
namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

// Writes every line; false on any I/O error (fprintf reports them through ferror).
bool writeLines(std::FILE* out, const WorldGeometry& geometry) {
    std::fprintf(out, "# shadowlab world geometry: %zu vertices, %zu triangles\n",
                 geometry.positions.size(), geometry.triangles.size());
    // 9 significant digits identify every float uniquely (FLT_DECIMAL_DIG).
    for (const glm::vec3& p : geometry.positions)
        std::fprintf(out, "v %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
    for (const glm::uvec3& t : geometry.triangles)
        std::fprintf(out, "f %u %u %u\n", t.x + 1, t.y + 1, t.z + 1);
    return std::ferror(out) == 0;
}

}  // namespace

void writeObj(const WorldGeometry& geometry, const std::string& path) {
    writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
        File out(std::fopen(temporary.c_str(), "wb"), &std::fclose);
        if (!out) throw std::runtime_error(std::string("cannot open for writing: ") + std::strerror(errno));
        const bool written = writeLines(out.get(), geometry);
        const bool closed = std::fclose(out.release()) == 0;   // flushes: a full disk shows here
        if (!written || !closed) throw std::runtime_error(std::string("cannot write: ") + std::strerror(errno));
    });
}

}  // namespace shadowlab
