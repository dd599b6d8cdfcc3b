#include "raster/vertex_stage.h"

#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowlab::raster {
namespace {

constexpr size_t kVertexGrain = 16384;

void resize(TransformedVertices& out, size_t n) {
    out.x.resize(n), out.y.resize(n), out.z.resize(n), out.w.resize(n);
    out.clipCode.resize(n), out.viewportCode.resize(n), out.window.resize(n);
}

// clip = M * (x, y, z, w): each output row summed left to right, never contracted.
template <class Position>
void transform(std::span<const Position> positions, const glm::mat4& m, const Viewport& viewport,
               TransformedVertices& out) {
    resize(out, positions.size());
    float* row[4] = {out.x.data(), out.y.data(), out.z.data(), out.w.data()};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, positions.size(), kVertexGrain), [&](const auto& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const Position& q = positions[i];
            const float w = Position::length() == 4 ? q[Position::length() - 1] : 1.0f;
            for (int r = 0; r < 4; ++r) row[r][i] = m[0][r] * q[0] + m[1][r] * q[1] + m[2][r] * q[2] + m[3][r] * w;
        }
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const glm::vec4 p = out.clipPosition(uint32_t(i));
            const bool projectable = p.w > 0.0f && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
                                     std::isfinite(p.w);
            const uint8_t code = uint8_t(clipOutcode(p, viewport.volume) | (projectable ? 0 : kNotProjectable));
            out.clipCode[i] = code;
            out.viewportCode[i] = uint8_t(viewportOutcode(p, viewport.volume));
            if (code == 0) out.window[i] = toWindow(p, viewport.width, viewport.height);
        }
    });
}

}  // namespace

void transformVertices(std::span<const glm::vec3> positions, const glm::mat4& clipFromObject, const Viewport& viewport,
                       TransformedVertices& out) {
    transform(positions, clipFromObject, viewport, out);
}

void transformVertices(std::span<const glm::vec4> positions, const glm::mat4& clipFromObject, const Viewport& viewport,
                       TransformedVertices& out) {
    transform(positions, clipFromObject, viewport, out);
}

}  // namespace shadowlab::raster
