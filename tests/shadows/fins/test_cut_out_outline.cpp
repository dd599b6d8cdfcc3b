// The outline of a cut-out's alpha texture as the fins' silhouette (shadows/silhouettes/
// cut_out_outline.h, docs/cut-outs.md):
//  - a texture's outline: hand-made textures (a plus sign, a ring, a texel at the border, a
//    repeated and mirrored checker) give the runs a hand count gives, in closed loops, with
//    the opaque texels on the left: every lattice edge between an opaque texel and a hole
//    (the alpha test's own texel rule, nearestTexelIndex) lies on exactly one run;
//  - mapped onto cards: each world edge lies between points the alpha test keeps (left, as
//    the light sees it) and drops (right), on mask-card and on a repeated card, the cards'
//    diagonals continued and their borders kept;
//  - fins, smoothies and penumbra maps on the foliage and on mask-card under a disk light
//    come closer to the soft reference than the hard shadow of the leaves without fins did,
//    with the same bytes at 1 and 2 threads.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "tests/shadows/soft_test_support.h"

#include "frame/registry.h"
#include "raster/nearest_texel.h"
#include "raster/thread_count.h"
#include "scenes/edge_adjacency.h"
#include "scenes/procedural.h"
#include "scenes/scene_file.h"
#include "shadows/silhouettes/cut_out_outline.h"
#include "tests/same_bits.h"

using namespace shadowlab;

namespace {

// A clamped texture from rows of '#' (opaque) and '.' (hole), the top row first.
WorldGeometry::CutOut texture(const std::vector<std::string>& rows, UvWrap wrap = {}) {
    WorldGeometry::CutOut t;
    t.height = int(rows.size()), t.width = int(rows[0].size());
    for (const std::string& row : rows) {
        for (char c : row) t.alpha.push_back(c == '#' ? 0.8f : 0.2f);
    }
    t.cutoff = 0.5f, t.wrap = wrap;
    return t;
}

// Opaque to the alpha test at lattice cell (i, j) (j up from the bottom), by the test's own
// rule at the cell's centre.
bool opaqueAt(const WorldGeometry::CutOut& t, int i, int j) {
    const glm::vec2 uv((float(i) + 0.5f) / float(t.width), (float(j) + 0.5f) / float(t.height));
    return t.alpha[size_t(nearestTexelIndex(t.width, t.height, t.wrap, uv))] >= t.cutoff;
}

// Loops of runs, each run's end the next one's start (the textures here have no two texels
// meeting at a corner only); 0 if a run has no successor.
int loopCount(const std::vector<TexelRun>& runs) {
    std::map<std::pair<int, int>, size_t> byStart;
    for (size_t k = 0; k < runs.size(); ++k) byStart[{runs[k].from.x, runs[k].from.y}] = k;
    if (byStart.size() != runs.size()) return 0;
    std::vector<bool> seen(runs.size(), false);
    int loops = 0;
    for (size_t k = 0; k < runs.size(); ++k) {
        if (seen[k]) continue;
        ++loops;
        for (size_t r = k; !seen[r];) {
            seen[r] = true;
            const auto next = byStart.find({runs[r].to.x, runs[r].to.y});
            if (next == byStart.end()) return 0;
            r = next->second;
        }
    }
    return loops;
}

// Twice the area the runs enclose, counter-clockwise positive (the shoelace sum): twice the
// opaque texels' count when every loop has the opaque side on its left.
int twiceArea(const std::vector<TexelRun>& runs) {
    int sum = 0;
    for (const TexelRun& r : runs) sum += r.from.x * r.to.y - r.to.x * r.from.y;
    return sum;
}

// Every lattice edge of the period (and of a clamped texture's border) lies on exactly one
// run exactly when the texels either side differ, and the run keeps the opaque one on its left.
void checkLatticeEdges(const WorldGeometry::CutOut& t, const TextureOutline& o) {
    const auto opaque = [&](int i, int j) {
        if ((!o.periodic.x && (i < 0 || i >= o.period.x)) || (!o.periodic.y && (j < 0 || j >= o.period.y))) return false;
        return opaqueAt(t, i, j);
    };
    // Which run covers the unit edge from p to p + step, walked forwards (+1) or backwards (-1).
    const auto covering = [&](glm::ivec2 p, glm::ivec2 step) {
        int found = 0, count = 0;
        for (const TexelRun& r : o.runs) {
            const glm::ivec2 d = glm::sign(r.to - r.from);
            if (d != step && d != -step) continue;
            const glm::ivec2 lo = glm::min(r.from, r.to), hi = glm::max(r.from, r.to);
            const bool on = step.x ? (p.y == lo.y && p.x >= lo.x && p.x + 1 <= hi.x) : (p.x == lo.x && p.y >= lo.y && p.y + 1 <= hi.y);
            if (on) ++count, found = d == step ? +1 : -1;
        }
        return count > 1 ? 2 : found;
    };
    for (int j = 0; j <= o.period.y; ++j) {
        for (int i = 0; i < o.period.x; ++i) {
            if (o.periodic.y && j == o.period.y) continue;
            const bool above = opaque(i, j), below = opaque(i, j - 1);
            INFO("horizontal lattice edge at " << i << ", " << j);
            CHECK(covering({i, j}, {1, 0}) == (above == below ? 0 : above ? +1 : -1));
        }
    }
    for (int i = 0; i <= o.period.x; ++i) {
        for (int j = 0; j < o.period.y; ++j) {
            if (o.periodic.x && i == o.period.x) continue;
            const bool left = opaque(i - 1, j), right = opaque(i, j);
            INFO("vertical lattice edge at " << i << ", " << j);
            CHECK(covering({i, j}, {0, 1}) == (left == right ? 0 : left ? +1 : -1));
        }
    }
}

}  // namespace

TEST_CASE("cut-out outline: a plus sign, a ring and a texel at the border give the runs a hand count gives") {
    struct Case {
        const char* name;
        std::vector<std::string> rows;
        size_t runs;
        int loops, opaqueTexels;
    };
    const Case cases[] = {
        // Twelve sides of the cross, one loop.
        {"plus", {".....", "..#..", ".###.", "..#..", "....."}, 12, 1, 5},
        // A 3 x 3 square with a hole: four sides outside (counter-clockwise), four inside (clockwise).
        {"ring", {".....", ".###.", ".#.#.", ".###.", "....."}, 8, 2, 8},
        // The top-left texel: two of its sides on the texture's border, which bounds it too.
        {"corner texel", {"#..", "...", "..."}, 4, 1, 1},
        // A bar along the bottom row, merged into one run per side.
        {"bar", {"....", "....", "####"}, 4, 1, 4},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const WorldGeometry::CutOut t = texture(c.rows);
        const TextureOutline o = textureOutline(t);
        CHECK(o.runs.size() == c.runs);
        CHECK(loopCount(o.runs) == c.loops);
        CHECK(twiceArea(o.runs) == 2 * c.opaqueTexels);
        checkLatticeEdges(t, o);
    }
    // The ring's hole is walked clockwise: its loop alone encloses -1 texel.
    const TextureOutline ring = textureOutline(texture(cases[1].rows));
    std::vector<TexelRun> hole;
    for (const TexelRun& r : ring.runs) {
        if (glm::all(glm::greaterThanEqual(glm::min(r.from, r.to), glm::ivec2(2))) &&
            glm::all(glm::lessThanEqual(glm::max(r.from, r.to), glm::ivec2(3)))) {
            hole.push_back(r);
        }
    }
    CHECK(hole.size() == 4);
    CHECK(twiceArea(hole) == -2);
}

TEST_CASE("cut-out outline: a repeated and mirrored texture's runs tile its period, none across the period's ends") {
    // The wrapped glTF card's checker (test_cut_outs.cpp): repeated along u, mirrored along v.
    const WorldGeometry::CutOut t = texture({"#.", ".#"}, {TextureWrap::Repeat, TextureWrap::MirroredRepeat});
    const TextureOutline o = textureOutline(t);
    CHECK(o.period == glm::ivec2(2, 4));
    CHECK(o.periodic == glm::bvec2(true, true));
    checkLatticeEdges(t, o);
    for (const TexelRun& r : o.runs) {
        CHECK(glm::all(glm::greaterThanEqual(glm::min(r.from, r.to), glm::ivec2(0))));
        CHECK(glm::all(glm::lessThanEqual(glm::max(r.from, r.to), o.period)));
    }
    // Mirrored rows 1 and 2 read the same texel row: no run between them.
    for (const TexelRun& r : o.runs) CHECK(!(r.from.y == 2 && r.to.y == 2));
}

namespace {

std::string assetScene(const std::string& name) { return std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/" + name; }

// The disk light test_cut_outs.cpp puts over mask-card for the soft families.
Light maskCardDisk() {
    return Light{.type = LightType::Disk, .position = {1.5f, 5.0f, 2.0f},
                 .direction = glm::normalize(glm::vec3(-1.5f, -5.0f, -2.0f)), .radius = 0.4f, .intensity = glm::vec3(1.0f)};
}

// A 2 m card at y = 1 (two triangles, one diagonal), texture coordinates (0, 0) to
// (uvMax, uvMax), its 4 x 4 texture repeated along u and mirrored along v; a ground under it.
Scene repeatedCard(float uvMax) {
    Scene scene;
    Mesh card;
    card.source = "procedural:test-card";
    card.positions = {{0, 1, 0}, {0, 1, 2}, {2, 1, 2}, {2, 1, 0}};   // faces +y
    card.triangles = {{0, 1, 2}, {0, 2, 3}};
    const glm::vec2 uv[4] = {{0, uvMax}, {0, 0}, {uvMax, 0}, {uvMax, uvMax}};
    for (const glm::uvec3& t : card.triangles) {
        for (int c = 0; c < 3; ++c) card.cornerUvs.push_back(uv[t[c]]);
    }
    scene.meshes = {card, makeGrid(glm::vec2(6.0f), glm::ivec2(1))};
    const WorldGeometry::CutOut t = texture({"##..", "#..#", ".##.", "#.##"});
    scene.alphaTextures = {{.source = "test", .width = t.width, .height = t.height, .alpha = t.alpha,
                            .wrap = {TextureWrap::Repeat, TextureWrap::MirroredRepeat}}};
    scene.materials = {Material{.name = "card", .alphaTexture = 0, .alphaCutoff = t.cutoff}, Material{.name = "ground"}};
    scene.instances = {{.name = "card", .mesh = 0, .material = 0}, {.name = "ground", .mesh = 1, .material = 1}};
    scene.lights = {Light{.type = LightType::Disk, .position = {1.3f, 5.0f, 0.7f}, .direction = {0.0f, -1.0f, 0.0f},
                          .radius = 0.3f}};
    scene.camera = {.eye = {1.0f, 6.0f, 4.0f}, .target = {1.0f, 0.0f, 1.0f}, .width = 160, .height = 100};
    return scene;
}

// Whether the alpha test keeps point p of instance `instance` (false off its triangles): the
// texture coordinates interpolated at p, in float, read by nearestTexelIndex.
bool keptAt(const WorldGeometry& world, const std::vector<InstanceRange>& ranges, uint32_t instance, const glm::dvec3& p) {
    const InstanceRange& r = ranges[instance];
    for (uint32_t k = 0; k < r.triangleCount; ++k) {
        const uint32_t t = r.firstTriangle + k;
        const glm::dvec3 a(world.positions[world.triangles[t].x]), b(world.positions[world.triangles[t].y]),
            c(world.positions[world.triangles[t].z]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double area = glm::dot(n, n);
        const double wb = glm::dot(glm::cross(p - a, c - a), n) / area, wc = glm::dot(glm::cross(b - a, p - a), n) / area;
        if (wb < 0.0 || wc < 0.0 || wb + wc > 1.0) continue;
        const glm::vec2 uv = float(1.0 - wb - wc) * world.cornerUvs[3 * t] + float(wb) * world.cornerUvs[3 * t + 1] +
                             float(wc) * world.cornerUvs[3 * t + 2];
        const WorldGeometry::CutOut& cut = world.cutOuts[size_t(world.triangleCutOut[t])];
        return cut.alpha[size_t(nearestTexelIndex(cut.width, cut.height, cut.wrap, uv))] >= cut.cutoff;
    }
    return false;
}

// Each outline edge of at least half a texel: at its midpoint, `offset` (m) to its left as the
// light's centre sees it, within the card's plane, the alpha test keeps the card, to its right
// drops it. Returns the edges checked.
size_t checkSides(const Scene& scene, const WorldGeometry& world, const CutOutOutline& o, const glm::dvec3& light,
                  double texel, double offset) {
    const std::vector<InstanceRange> ranges = instanceRanges(scene);
    size_t checked = 0;
    for (const SilhouetteEdge& e : o.edges) {
        const glm::dvec3 a(o.positions[e.from]), b(o.positions[e.to]);
        if (glm::length(b - a) < 0.5 * texel) continue;
        const uint32_t instance = o.vertexInstance[e.from];
        const glm::uvec3& t = world.triangles[ranges[instance].firstTriangle];
        const glm::dvec3 n = glm::normalize(glm::cross(glm::dvec3(world.positions[t.y]) - glm::dvec3(world.positions[t.x]),
                                                       glm::dvec3(world.positions[t.z]) - glm::dvec3(world.positions[t.x])));
        const glm::dvec3 mid = 0.5 * (a + b), d = glm::normalize(b - a);
        glm::dvec3 left = glm::normalize(glm::cross(n, d));
        if (glm::dot(left, glm::cross(light - mid, d)) < 0.0) left = -left;
        INFO("edge " << checked << " from " << a.x << ", " << a.y << ", " << a.z << " to " << b.x << ", " << b.y << ", " << b.z);
        CHECK(keptAt(world, ranges, instance, mid + offset * left));
        CHECK_FALSE(keptAt(world, ranges, instance, mid - offset * left));
        ++checked;
    }
    return checked;
}

CutOutOutline outlineOf(const PreparedScene& prepared) {
    const glm::dvec4 centre(glm::dvec3(prepared.scene().lights[0].position), 1.0);
    return cutOutOutline(prepared.scene(), prepared.world(), prepared.edgeAdjacency(), centre);
}

}  // namespace

TEST_CASE("cut-out outline: mask-card's world edges lie between what the alpha test keeps and drops, opaque on the left") {
    Scene scene = loadScene(assetScene("volumetric/mask-card.json"));
    scene.lights = {maskCardDisk()};
    const PreparedScene prepared(scene);
    const CutOutOutline o = outlineOf(prepared);
    CHECK(o.refusedInstances == 0);
    REQUIRE(o.edges.size() > 100);
    // 1 m cards of 64 texels: half a texel to either side.
    CHECK(checkSides(prepared.scene(), prepared.world(), o, glm::dvec3(scene.lights[0].position), 1.0 / 64.0, 0.5 / 64.0) ==
          o.edges.size());
    // Every outline vertex ends as many edges as it starts: closed loops, with fans at the corners.
    std::vector<int> balance(o.positions.size(), 0);
    for (const SilhouetteEdge& e : o.edges) ++balance[e.from], --balance[e.to];
    CHECK(std::ranges::count(balance, 0) == std::ssize(balance));
}

TEST_CASE("cut-out outline: a repeated, mirrored card's outline is the tiled texture's, its diagonal continued") {
    // Texture coordinates up to 2.5: two and a half periods along u, one and a quarter along v.
    const PreparedScene prepared(repeatedCard(2.5f));
    const CutOutOutline o = outlineOf(prepared);
    CHECK(o.refusedInstances == 0);
    // 2 m over 10 texels; a tenth of a texel to either side.
    CHECK(checkSides(prepared.scene(), prepared.world(), o, glm::dvec3(prepared.scene().lights[0].position), 0.2, 0.02) > 20);
    // No edge runs along the diagonal from (0, 1, 0) to (2, 1, 2).
    for (const SilhouetteEdge& e : o.edges) {
        const glm::vec3 a = o.positions[e.from], b = o.positions[e.to];
        CHECK_FALSE((std::abs(a.x - a.z) < 1e-6f && std::abs(b.x - b.z) < 1e-6f));
    }
    std::vector<int> balance(o.positions.size(), 0);
    for (const SilhouetteEdge& e : o.edges) ++balance[e.from], --balance[e.to];
    CHECK(std::ranges::count(balance, 0) == std::ssize(balance));
}

TEST_CASE("cut-out outline: a clamped texture beyond [0, 1], or a texture repeated too often, is refused") {
    Scene scene = repeatedCard(1.5f);
    scene.alphaTextures[0].wrap = {};
    const PreparedScene prepared(scene);
    const CutOutOutline o = outlineOf(prepared);
    CHECK(o.refusedInstances == 1);
    CHECK(o.edges.empty());
    Scene inside = repeatedCard(1.0f);
    inside.alphaTextures[0].wrap = {};
    const CutOutOutline kept = outlineOf(PreparedScene(inside));
    CHECK(kept.refusedInstances == 0);
    CHECK(!kept.edges.empty());
    // 16,000 periods along u times 8,000 along v: far too many runs to clip, refused before any is.
    const CutOutOutline tooMany = outlineOf(PreparedScene(repeatedCard(16000.0f)));
    CHECK(tooMany.refusedInstances == 1);
    CHECK(tooMany.edges.empty());
}


// Under a disk light, at 160 x 100 against the soft reference at 12 x 12 samples. The leaves'
// hard shadow without fins (before the outline, docs/cut-outs.md) gave RMS 0.094 on the
// foliage and 0.146 on mask-card for all three, and no pixel between lit and shadowed. From
// the outline: fins 0.070 and 0.103, smoothies 0.122 and 0.130, penumbra maps 0.122 and
// 0.143: outer fins alone over-estimate the umbra (Cai et al., section 7.1), which on the
// foliage's small leaves, whose true umbra is small, costs more than the penumbra gains.
TEST_CASE("cut-out outline: fins from the outline come closer to the soft reference, and all three draw a penumbra") {
    const test::SoftScene foliage(test::smallScene(assetScene("volumetric/foliage-cards-disk.json"), 160, 100), 12);
    Scene mask = test::smallScene(assetScene("volumetric/mask-card.json"), 160, 100);
    mask.lights = {maskCardDisk()};
    const test::SoftScene maskCard(mask, 12);
    struct Bound {
        const char* technique;
        double foliage, mask;   // RMS below
    };
    for (const Bound& b : {Bound{"fins", 0.08, 0.12}, Bound{"smoothies", 0.15, 0.138}, Bound{"penumbra-maps", 0.15, 0.15}}) {
        CAPTURE(b.technique);
        for (const test::SoftScene* s : {&foliage, &maskCard}) {
            CAPTURE(s->scene.name);
            std::vector<float> V[2];
            for (int threads : {1, 2}) V[threads - 1] = withThreads(threads, [&] { return s->run(b.technique).visibility; });
            CHECK(test::sameBytes(V[0], V[1]));
            CHECK(s->rms(V[0]) < (s == &foliage ? b.foliage : b.mask));
            // A penumbra: more than 1% of the hit pixels between lit and shadowed (the hard shadow: none).
            size_t hit = 0, between = 0;
            for (size_t k = 0; k < V[0].size(); ++k) {
                hit += s->gbuffer.hit[k];
                between += s->gbuffer.hit[k] && V[0][k] > 0.02f && V[0][k] < 0.98f;
            }
            CHECK(double(between) > 0.01 * double(hit));
        }
    }
}
