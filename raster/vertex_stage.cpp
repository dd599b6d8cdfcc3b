#include "raster/vertex_stage.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowlab::raster {
namespace {

constexpr size_t kVertexGrain = 16384;

void resize(ClipVertices& out, size_t n) {
    out.x.resize(n);
    out.y.resize(n);
    out.z.resize(n);
    out.w.resize(n);
}

// clip = M * (x, y, z, w): each output row summed left to right, never contracted.
template <class Position>
void transform(std::span<const Position> positions, const glm::mat4& m, ClipVertices& out) {
    resize(out, positions.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, positions.size(), kVertexGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const glm::vec4 p = glm::vec4(positions[i][0], positions[i][1], positions[i][2],
                                          Position::length() == 4 ? positions[i][Position::length() - 1] : 1.0f);
            float* row[4] = {out.x.data(), out.y.data(), out.z.data(), out.w.data()};
            for (int r = 0; r < 4; ++r) row[r][i] = m[0][r] * p.x + m[1][r] * p.y + m[2][r] * p.z + m[3][r] * p.w;
        }
    });
}

}  // namespace

void transformVertices(std::span<const glm::vec3> positions, const glm::mat4& clipFromObject, ClipVertices& out) {
    transform(positions, clipFromObject, out);
}

void transformVertices(std::span<const glm::vec4> positions, const glm::mat4& clipFromObject, ClipVertices& out) {
    transform(positions, clipFromObject, out);
}

}  // namespace shadowlab::raster
