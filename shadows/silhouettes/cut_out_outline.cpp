#include "shadows/silhouettes/cut_out_outline.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

// Texel coordinates a clamped axis may pass 0 or its size by (float texture coordinates of
// 0 and 1 written with rounding): the sliver beyond reads the edge texel, as inside.
constexpr double kClampTolerance = 1e-3;
// Runs clipped per instance at most: the texture's runs times the periods its triangles
// overlap. A texture repeated thousands of times over a ground would otherwise take seconds
// and millions of fins a frame; such an instance is refused.
constexpr double kMaxClippedRuns = double(1 << 20);

int64_t floorMod(int64_t i, int64_t n) { return ((i % n) + n) % n; }

// The texel index along one axis that lattice cell i reads (nearest_texel.inl's wrap).
int wrappedTexel(TextureWrap wrap, int64_t i, int n) {
    switch (wrap) {
        case TextureWrap::Repeat: return int(floorMod(i, n));
        case TextureWrap::MirroredRepeat: {
            const int64_t m = floorMod(i, 2 * int64_t(n));
            return int(m < n ? m : 2 * n - 1 - m);
        }
        case TextureWrap::ClampToEdge: break;
    }
    return int(std::clamp<int64_t>(i, 0, n - 1));
}

// Whether lattice cell (i, j), j counted up from the bottom row, is opaque to the alpha test.
bool opaqueCell(const WorldGeometry::CutOut& t, int64_t i, int64_t j) {
    const int column = wrappedTexel(t.wrap.u, i, t.width);
    const int row = t.height - 1 - wrappedTexel(t.wrap.v, j, t.height);
    return t.alpha[size_t(row) * size_t(t.width) + size_t(column)] >= t.cutoff;
}

int periodOf(TextureWrap wrap, int n) { return wrap == TextureWrap::MirroredRepeat ? 2 * n : n; }

// The runs along one lattice line of the period: unit edges where `opaqueBefore(k)` (the cell
// to the left of a vertical line, below a horizontal one) differs from `opaqueAfter(k)`,
// consecutive ones of the same direction merged. `corner(k)` is the lattice point at k.
template <class Before, class After, class Corner>
void lineRuns(int cells, Before opaqueBefore, After opaqueAfter, Corner corner, bool forwardWhenBefore,
              std::vector<TexelRun>& runs) {
    int start = 0, direction = 0;   // the open run [start, k): +1 forward, -1 backward, 0 none
    for (int k = 0; k <= cells; ++k) {
        int d = 0;
        if (k < cells) {
            const bool before = opaqueBefore(k), after = opaqueAfter(k);
            if (before != after) d = before == forwardWhenBefore ? +1 : -1;
        }
        if (d == direction) continue;
        if (direction > 0) runs.push_back({corner(start), corner(k)});
        if (direction < 0) runs.push_back({corner(k), corner(start)});
        start = k, direction = d;
    }
}

}  // namespace

TextureOutline textureOutline(const WorldGeometry::CutOut& texture) {
    TextureOutline o;
    o.periodic = {texture.wrap.u != TextureWrap::ClampToEdge, texture.wrap.v != TextureWrap::ClampToEdge};
    o.period = {periodOf(texture.wrap.u, texture.width), periodOf(texture.wrap.v, texture.height)};
    // Beyond a clamped axis, holes: the card's own edges bound it there (step 2).
    const auto opaque = [&](int i, int j) {
        if ((!o.periodic.x && (i < 0 || i >= o.period.x)) || (!o.periodic.y && (j < 0 || j >= o.period.y))) return false;
        return opaqueCell(texture, i, j);
    };
    // A periodic axis's last line is the next period's first.
    const int columnLines = o.period.x + (o.periodic.x ? 0 : 1), rowLines = o.period.y + (o.periodic.y ? 0 : 1);
    for (int j = 0; j < rowLines; ++j) {   // opaque above: walk +x, with the opaque side on the left
        lineRuns(o.period.x, [&](int i) { return opaque(i, j - 1); }, [&](int i) { return opaque(i, j); },
                 [&](int i) { return glm::ivec2(i, j); }, false, o.runs);
    }
    for (int i = 0; i < columnLines; ++i) {   // opaque on the left: walk +y
        lineRuns(o.period.y, [&](int j) { return opaque(i - 1, j); }, [&](int j) { return opaque(i, j); },
                 [&](int j) { return glm::ivec2(i, j); }, true, o.runs);
    }
    return o;
}

namespace {

double texelCross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// One cut-out instance's outline (steps 2 and 3), its vertices shared through keys: a
// corner by its welded vertex, a point on an edge by the edge and its fraction, a lattice
// point inside a triangle by the triangle and the point.
class InstanceOutline {
public:
    InstanceOutline(const Scene& scene, const WorldGeometry& world, const EdgeAdjacency& adjacency,
                    const InstanceRange& range, const std::vector<TextureOutline>& outlines, const glm::dvec4& light)
        : world_(world), adjacency_(adjacency), range_(range), mesh_(scene.meshes[range.mesh]), outlines_(outlines),
          signs_(instanceCasterSigns(world, range, light, false)) {}

    // False (and nothing kept) when a triangle's texture coordinates are not finite, or a
    // clamped axis leaves [0, 1], or the instance would clip more than kMaxClippedRuns.
    bool build() {
        double clippedRuns = 0.0;
        for (uint32_t m = 0; m < range_.triangleCount; ++m) {
            if (!accepted(m, clippedRuns)) return false;
        }
        for (uint32_t m = 0; m < range_.triangleCount; ++m) triangle(m);
        return true;
    }

    std::vector<glm::vec3> positions;
    std::vector<SilhouetteEdge> edges;

private:
    // One triangle seen in texel space: corners in counter-clockwise order there, so the
    // triangle lies left of each edge k = corner k -> corner k + 1.
    struct TexelTriangle {
        uint32_t mesh, world;
        int cutOut;
        glm::dvec2 q[3];
        glm::dvec2 meshQ[3];   // the same in the mesh's corner order
        uint32_t welded[3];
        int meshEdge[3];       // index into adjacency.edges of edge k
        bool border[3];        // edge k bounds the opaque part here (no neighbour continues it)
        bool flip;             // the texel-space order is against the light's (step 3)
        double area2;          // twice the signed area in the mesh's corner order
    };

    glm::dvec2 texelCoordinates(uint32_t worldTriangle, int corner, const WorldGeometry::CutOut& t) const {
        const glm::vec2 uv = world_.cornerUvs[3 * size_t(worldTriangle) + size_t(corner)];
        return {double(uv.x) * t.width, double(uv.y) * t.height};
    }

    bool accepted(uint32_t m, double& clippedRuns) const {
        const uint32_t w = range_.firstTriangle + m;
        const int c = world_.triangleCutOut[w];
        if (c < 0) return true;
        const WorldGeometry::CutOut& t = world_.cutOuts[size_t(c)];
        const TextureOutline& outline = outlines_[size_t(c)];
        glm::dvec2 lo(INFINITY), hi(-INFINITY);
        for (int k = 0; k < 3; ++k) {
            const glm::dvec2 q = texelCoordinates(w, k, t);
            if (!std::isfinite(q.x) || !std::isfinite(q.y)) return false;
            lo = glm::min(lo, q), hi = glm::max(hi, q);
        }
        double periods = 1.0;
        for (int axis = 0; axis < 2; ++axis) {
            const double size = axis == 0 ? t.width : t.height;
            if (!outline.periodic[axis] && (lo[axis] < -kClampTolerance || hi[axis] > size + kClampTolerance)) return false;
            if (outline.periodic[axis]) {
                periods *= std::max(1.0, std::ceil(hi[axis] / outline.period[axis]) - std::floor(lo[axis] / outline.period[axis]));
            }
        }
        clippedRuns += periods * double(outline.runs.size());
        return clippedRuns <= kMaxClippedRuns;
    }

    int meshEdgeIndex(uint32_t a, uint32_t b) const {
        const auto key = std::minmax(a, b);
        const auto it = std::lower_bound(adjacency_.edges.begin(), adjacency_.edges.end(), key, [](const MeshEdge& e, auto k) {
            return std::pair(e.v0, e.v1) < std::pair(k.first, k.second);
        });
        return it != adjacency_.edges.end() && it->v0 == key.first && it->v1 == key.second ? int(it - adjacency_.edges.begin()) : -1;
    }

    // Texture coordinates of triangle m's corner at welded vertex v.
    glm::vec2 uvAt(uint32_t m, uint32_t v) const {
        const glm::uvec3& tri = mesh_.triangles[m];
        for (int c = 0; c < 3; ++c) {
            if (adjacency_.weldedVertex[tri[c]] == v) return world_.cornerUvs[3 * size_t(range_.firstTriangle + m) + size_t(c)];
        }
        return glm::vec2(NAN);
    }

    // A neighbour continues the opaque part across the edge when the texture runs on unbroken:
    // one other triangle, the same cut-out and texture coordinates at both ends, and the two
    // cast with the same orientation (their uses cancel, as at a mesh's non-silhouette edge).
    bool continued(const TexelTriangle& t, int edge) const {
        if (edge < 0) return false;
        const MeshEdge& e = adjacency_.edges[size_t(edge)];
        if (e.useCount != 2) return false;
        const EdgeUse& x = adjacency_.uses[e.firstUse];
        const EdgeUse& y = adjacency_.uses[e.firstUse + 1];
        const uint32_t other = x.triangle == t.mesh ? y.triangle : x.triangle;
        if (world_.triangleCutOut[range_.firstTriangle + other] != t.cutOut) return false;
        if (x.direction * signs_[x.triangle].light + y.direction * signs_[y.triangle].light != 0) return false;
        for (uint32_t v : {e.v0, e.v1}) {
            if (uvAt(t.mesh, v) != uvAt(other, v)) return false;
        }
        return true;
    }

    bool texelTriangle(uint32_t m, TexelTriangle& t) const {
        t.mesh = m, t.world = range_.firstTriangle + m;
        t.cutOut = world_.triangleCutOut[t.world];
        if (t.cutOut < 0) return false;
        const WorldGeometry::CutOut& texture = world_.cutOuts[size_t(t.cutOut)];
        for (int c = 0; c < 3; ++c) t.meshQ[c] = texelCoordinates(t.world, c, texture);
        t.area2 = texelCross(t.meshQ[1] - t.meshQ[0], t.meshQ[2] - t.meshQ[0]);
        if (t.area2 == 0.0) return false;
        const int order[2][3] = {{0, 2, 1}, {0, 1, 2}};
        const glm::uvec3& tri = mesh_.triangles[m];
        for (int k = 0; k < 3; ++k) {
            const int c = order[t.area2 > 0.0][k];
            t.q[k] = t.meshQ[c];
            t.welded[k] = adjacency_.weldedVertex[tri[c]];
        }
        if (t.welded[0] == t.welded[1] || t.welded[1] == t.welded[2] || t.welded[2] == t.welded[0]) return false;
        for (int k = 0; k < 3; ++k) {
            t.meshEdge[k] = meshEdgeIndex(t.welded[k], t.welded[(k + 1) % 3]);
            t.border[k] = !continued(t, t.meshEdge[k]);
        }
        t.flip = (t.area2 > 0.0) != (signs_[m].light > 0);
        return true;
    }

    uint32_t vertex(const std::tuple<int, int64_t, int64_t, int64_t>& key, const glm::dvec3& p) {
        const auto [it, added] = vertices_.try_emplace(key, uint32_t(positions.size()));
        if (added) positions.push_back(glm::vec3(p));
        return it->second;
    }
    glm::dvec3 worldOf(uint32_t welded) const { return glm::dvec3(world_.positions[range_.firstVertex + welded]); }
    uint32_t corner(uint32_t welded) { return vertex({0, welded, 0, 0}, worldOf(welded)); }

    // The point at fraction s along edge k from its smaller welded vertex to its larger one.
    uint32_t edgePoint(const TexelTriangle& t, int k, double s) {
        const uint32_t v0 = std::min(t.welded[k], t.welded[(k + 1) % 3]), v1 = std::max(t.welded[k], t.welded[(k + 1) % 3]);
        if (!(s > 0.0)) return corner(v0);
        if (!(s < 1.0)) return corner(v1);
        const glm::dvec3 p = worldOf(v0) + s * (worldOf(v1) - worldOf(v0));
        return vertex({1, t.meshEdge[k], int64_t(std::llround(std::ldexp(s, 40))), 0}, p);
    }

    // Edge k's ends in texel space, from its smaller welded vertex to its larger one.
    static std::pair<glm::dvec2, glm::dvec2> canonicalEnds(const TexelTriangle& t, int k) {
        const int a = k, b = (k + 1) % 3;
        return t.welded[a] < t.welded[b] ? std::pair(t.q[a], t.q[b]) : std::pair(t.q[b], t.q[a]);
    }

    // The fraction along edge k where it crosses the lattice line `axis` = value: one
    // expression for the runs that cross the edge and the edge's own pieces, so they meet.
    static double crossing(const TexelTriangle& t, int k, int axis, double value) {
        const auto [p0, p1] = canonicalEnds(t, k);
        return (value - p0[axis]) / (p1[axis] - p0[axis]);
    }

    // A lattice point inside the triangle, by its barycentric coordinates in texel space:
    // the triangle's affine map from texture coordinates to world space.
    uint32_t interiorPoint(const TexelTriangle& t, const glm::i64vec2& p) {
        const glm::dvec2 d = glm::dvec2(p) - t.meshQ[0];
        const double b1 = texelCross(d, t.meshQ[2] - t.meshQ[0]) / t.area2, b2 = texelCross(t.meshQ[1] - t.meshQ[0], d) / t.area2;
        const glm::uvec3& tri = world_.triangles[t.world];
        const glm::dvec3 w = (1.0 - b1 - b2) * glm::dvec3(world_.positions[tri.x]) + b1 * glm::dvec3(world_.positions[tri.y]) +
                             b2 * glm::dvec3(world_.positions[tri.z]);
        return vertex({2, t.world, p.x, p.y}, w);
    }

    void emit(const TexelTriangle& t, uint32_t from, uint32_t to) {
        if (from == to) return;
        edges.push_back(t.flip ? SilhouetteEdge{to, from} : SilhouetteEdge{from, to});
    }

    void triangle(uint32_t m) {
        TexelTriangle t;
        if (!texelTriangle(m, t)) return;
        const TextureOutline& outline = outlines_[size_t(t.cutOut)];
        glm::dvec2 lo = glm::min(t.q[0], glm::min(t.q[1], t.q[2])), hi = glm::max(t.q[0], glm::max(t.q[1], t.q[2]));
        glm::i64vec2 first(0), last(0);   // the periods the triangle overlaps
        for (int axis = 0; axis < 2; ++axis) {
            if (!outline.periodic[axis]) continue;
            first[axis] = int64_t(std::floor(lo[axis] / outline.period[axis]));
            last[axis] = std::max(first[axis], int64_t(std::ceil(hi[axis] / outline.period[axis])) - 1);
        }
        for (int64_t a = first.x; a <= last.x; ++a) {
            for (int64_t b = first.y; b <= last.y; ++b) {
                const glm::i64vec2 shift(a * outline.period.x, b * outline.period.y);
                for (const TexelRun& r : outline.runs) clipRun(t, glm::i64vec2(r.from) + shift, glm::i64vec2(r.to) + shift);
            }
        }
        for (int k = 0; k < 3; ++k) {
            if (t.border[k]) borderPieces(t, k);
        }
    }

    // A run A -> B (opaque on its left) clipped to the triangle (Cyrus and Beck 1978).
    void clipRun(const TexelTriangle& t, const glm::i64vec2& A, const glm::i64vec2& B) {
        const glm::dvec2 a(A), b(B);
        const int axis = A.y == B.y ? 1 : 0;   // the run lies on the line `axis` = a[axis]
        double tEnter = 0.0, tExit = 1.0;
        int enterEdge = -1, exitEdge = -1, startEdge = -1, endEdge = -1;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec2 d = t.q[(k + 1) % 3] - t.q[k];
            const double fa = texelCross(d, a - t.q[k]), fb = texelCross(d, b - t.q[k]);
            if (fa == 0.0 && fb == 0.0) {   // along edge k: kept once, by the triangle on its opaque side
                if (t.border[k] || glm::dot(d, b - a) < 0.0) return;
                startEdge = endEdge = k;
                continue;
            }
            if (fa <= 0.0 && fb <= 0.0) return;   // outside, or touching the edge's line at one end
            if (fa == 0.0) startEdge = k;
            if (fb == 0.0) endEdge = k;
            if (fa < 0.0 && fb > 0.0) {
                const double s = fa / (fa - fb);
                if (s > tEnter) tEnter = s, enterEdge = k;
            } else if (fa > 0.0 && fb < 0.0) {
                const double s = fa / (fa - fb);
                if (s < tExit) tExit = s, exitEdge = k;
            }
        }
        if (!(tEnter < tExit)) return;
        // Points on an edge: where the run's line crosses it, or (along the edge) where the
        // line across it through the point does.
        const auto onEdge = [&](int k, const glm::dvec2& p) {
            const glm::dvec2 d = t.q[(k + 1) % 3] - t.q[k];
            const int line = d[axis] != 0.0 ? axis : 1 - axis;
            return edgePoint(t, k, crossing(t, k, line, p[line]));
        };
        const uint32_t from = enterEdge >= 0 ? onEdge(enterEdge, a) : startEdge >= 0 ? onEdge(startEdge, a) : interiorPoint(t, A);
        const uint32_t to = exitEdge >= 0 ? onEdge(exitEdge, b) : endEdge >= 0 ? onEdge(endEdge, b) : interiorPoint(t, B);
        emit(t, from, to);
    }

    // Edge k's pieces whose texel on the triangle's side is opaque, walked with the triangle
    // on the left; split where the edge crosses the lattice, consecutive opaque pieces merged.
    void borderPieces(const TexelTriangle& t, int k) {
        const auto [p0, p1] = canonicalEnds(t, k);
        std::vector<double> cuts = {0.0, 1.0};
        for (int axis = 0; axis < 2; ++axis) {
            const double lo = std::min(p0[axis], p1[axis]), hi = std::max(p0[axis], p1[axis]);
            for (double line = std::floor(lo) + 1.0; line < hi; line += 1.0) cuts.push_back(crossing(t, k, axis, line));
        }
        std::sort(cuts.begin(), cuts.end());
        const glm::dvec2 d = t.q[(k + 1) % 3] - t.q[k];
        const glm::dvec2 inward(-d.y, d.x);
        const bool forward = t.welded[k] < t.welded[(k + 1) % 3];   // the walk runs p0 -> p1
        const WorldGeometry::CutOut& texture = world_.cutOuts[size_t(t.cutOut)];
        const auto innerCell = [&](double c, double n) { return int64_t(c == std::floor(c) ? (n > 0.0 ? c : c - 1.0) : std::floor(c)); };
        double openFrom = -1.0;   // start of the open opaque stretch, or -1
        for (size_t i = 0; i + 1 < cuts.size(); ++i) {
            if (!(cuts[i + 1] > cuts[i])) continue;
            const glm::dvec2 mid = p0 + 0.5 * (cuts[i] + cuts[i + 1]) * (p1 - p0);
            const bool opaque = opaqueCell(texture, innerCell(mid.x, inward.x), innerCell(mid.y, inward.y));
            if (opaque && openFrom < 0.0) openFrom = cuts[i];
            if (!opaque && openFrom >= 0.0) stretch(t, k, openFrom, cuts[i], forward), openFrom = -1.0;
        }
        if (openFrom >= 0.0) stretch(t, k, openFrom, 1.0, forward);
    }
    void stretch(const TexelTriangle& t, int k, double s0, double s1, bool forward) {
        const uint32_t a = edgePoint(t, k, s0), b = edgePoint(t, k, s1);
        forward ? emit(t, a, b) : emit(t, b, a);
    }

    const WorldGeometry& world_;
    const EdgeAdjacency& adjacency_;
    InstanceRange range_;
    const Mesh& mesh_;
    const std::vector<TextureOutline>& outlines_;
    std::vector<CasterSigns> signs_;
    std::map<std::tuple<int, int64_t, int64_t, int64_t>, uint32_t> vertices_;
};

}  // namespace

CutOutOutline cutOutOutline(const Scene& scene, const WorldGeometry& world, const std::vector<EdgeAdjacency>& adjacency,
                            const glm::dvec4& light) {
    CutOutOutline out;
    if (world.cutOuts.empty()) return out;
    std::vector<TextureOutline> outlines;
    for (const WorldGeometry::CutOut& t : world.cutOuts) outlines.push_back(textureOutline(t));
    const std::vector<InstanceRange> ranges = instanceRanges(scene);
    std::vector<std::vector<glm::vec3>> positions(ranges.size());
    std::vector<std::vector<SilhouetteEdge>> edges(ranges.size());
    std::vector<uint8_t> refused(ranges.size(), 0);
    tbb::parallel_for(size_t(0), ranges.size(), [&](size_t i) {
        const InstanceRange& r = ranges[i];
        if (r.triangleCount == 0 || world.triangleCutOut[r.firstTriangle] < 0) return;
        InstanceOutline o(scene, world, adjacency[r.mesh], r, outlines, light);
        refused[i] = !o.build();
        if (!refused[i]) positions[i] = std::move(o.positions), edges[i] = std::move(o.edges);
    });
    for (size_t i = 0; i < ranges.size(); ++i) {   // in instance order, whatever the threads did
        const uint32_t base = uint32_t(out.positions.size());
        out.positions.insert(out.positions.end(), positions[i].begin(), positions[i].end());
        out.vertexInstance.insert(out.vertexInstance.end(), positions[i].size(), uint32_t(i));
        for (const SilhouetteEdge& e : edges[i]) out.edges.push_back({base + e.from, base + e.to});
        out.refusedInstances += refused[i];
    }
    return out;
}

}  // namespace shadowlab
