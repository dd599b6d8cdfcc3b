// A light cut into 1, 4, 16, 64 and more patches (differential/shaft_hierarchy.h
// and preprocess.cpp; Gibson et al. 2003 sections 6 and 6.1): the 2% rule judges shafts, and
// a light cut into n patches is n shafts, each of which may fall under it. However finely a
// window or a sky is cut, the shafts must leave out under 2% of any receiver vertex's light;
// and the shadow a box casts from a window onto the floor must converge as the window is cut
// finer, against the exact differential reference of the same model, not lose the light.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "differential/composite.h"
#include "differential/differential_reference.h"
#include "differential/environment_dome.h"
#include "scenes/procedural.h"
#include "shading/environment/environment_map.h"
#include "shading/luminance.h"

using namespace shadowlab;

namespace {

// A 4 x 4 m floor of 0.25 m patches under a ceiling panel (one patch) and a 1.4 x 1.2 m
// window in the plane x = 2 cut into cells x cells patches (as the room's, without its
// walls); a 0.3 x 0.4 x 0.3 m box on the floor 0.85 m from the window.
CompositingScene cutWindowScene(int cells) {
    CompositingScene scene;
    scene.name = "cut-window";
    scene.camera.eye = {0.0f, 3.0f, 2.5f};
    scene.camera.target = {0.4f, 0.0f, -0.2f};
    scene.camera.fovyDeg = 60.0f;
    scene.camera.width = 96;
    scene.camera.height = 64;
    scene.camera.zNear = 0.05f;
    scene.camera.zFar = 20.0f;
    scene.surfaces = {
        {"floor", {-2, 0, 2}, {4, 0, 0}, {0, 0, -4}, 16, 16, glm::dvec3(0.4), {}},
        {"ceiling panel", {-0.5, 2.49, -0.3}, {1, 0, 0}, {0, 0, 0.6}, 1, 1, glm::dvec3(0.0), {{9.0, 8.2, 7.0}}},
        {"window", {1.99, 0.9, -0.7}, {0, 0, 1.4}, {0, 1.2, 0}, cells, cells, glm::dvec3(0.0), {{6.0, 7.0, 8.5}}},
    };
    scene.objects = {{makeBox({0.85f, 0.0f, -0.15f}, {1.15f, 0.4f, 0.15f}), glm::dvec3(0.7), {glm::mat4(1.0f)}}};
    return scene;
}

// A 4 x 4 m ground of 0.5 m patches under a sky of one radiance cut into columns x rows
// patches on a dome of 100 m.
CompositingScene cutSkyScene(int columns, int rows) {
    CompositingScene scene;
    scene.name = "cut-sky";
    scene.camera.eye = {0.0f, 3.0f, 3.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.width = 32;
    scene.camera.height = 24;
    scene.camera.zFar = 1000.0f;
    scene.surfaces = {{"ground", {-2, 0, 2}, {4, 0, 0}, {0, 0, -4}, 8, 8, glm::dvec3(0.3), {}}};
    for (PatchSurface& sky : environmentDome(constantEnvironment(64, 32, glm::vec3(1.0f)), columns, rows, 100.0)) {
        scene.surfaces.push_back(std::move(sky));
    }
    scene.objects = {{makeBox({-0.2f, 0.0f, -0.2f}, {0.2f, 0.5f, 0.2f}), glm::dvec3(0.7), {glm::mat4(1.0f)}}};
    return scene;
}

// Every radiant patch a source, so that the source set (section 4) chooses none of a light's
// patches over another and only the shaft hierarchy decides what is listed.
DifferentialModel everyPatchASource(const CompositingScene& scene) {
    PreprocessSettings settings;
    settings.sourceShare = 1.0;
    return preprocess(scene, settings);
}

// The largest share of a receiver vertex's light (its share of the source set's, per
// receiver patch it is a corner of) that no leaf shaft over that patch carries: what the
// pruning leaves out there, computed from the leaves (each source and receiver pair under
// one leaf at most).
double largestShareLeftOut(const DifferentialModel& m) {
    const TransferTable& t = m.transfers;
    const size_t S = t.sources.size();
    const auto row = [&](uint32_t patch, int corner) {
        return size_t(t.rowOfVertex[m.model.patches[patch].vertex[corner]]);
    };
    std::vector<std::array<double, 4>> carried(m.model.patches.size(), {0.0, 0.0, 0.0, 0.0});
    for (const ShaftNode& shaft : m.shafts.nodes) {
        if (!shaft.leaf()) continue;
        const ReceiverNode& r = m.receiverOctree.nodes[size_t(shaft.receiver)];
        forEachPatch(m.sourceTree, shaft.source, [&](uint32_t s) {
            for (uint32_t k = r.firstPatch; k < r.firstPatch + r.patchCount; ++k) {
                const uint32_t p = t.receiverPatches[m.receiverOctree.patches[k]];
                for (int c = 0; c < 4; ++c) carried[p][size_t(c)] += double(luminance(t.L[row(p, c) * S + s]));
            }
        });
    }
    double largest = 0.0;
    for (const uint32_t p : t.receiverPatches) {
        for (int c = 0; c < 4; ++c) {
            double all = 0.0;
            for (size_t s = 0; s < S; ++s) all += double(luminance(t.L[row(p, c) * S + s]));
            const double total = luminance(t.total[row(p, c)]);
            REQUIRE(carried[p][size_t(c)] <= all * (1.0 + 1e-6));   // no pair under two leaves
            if (total > 0.0) largest = std::max(largest, (all - carried[p][size_t(c)]) / total);
        }
    }
    return largest;
}

// The luminance an image takes off the photograph, summed over the pixels off the object.
double lightTaken(const DifferentialModel& m, const std::vector<glm::vec3>& image, const std::vector<uint8_t>& object) {
    double sum = 0.0;
    for (size_t k = 0; k < image.size(); ++k) {
        if (!object[k]) sum += double(luminance(m.background[k])) - double(luminance(image[k]));
    }
    return sum;
}

}  // namespace

TEST_CASE("differential shafts: however finely a window or a sky is cut, no receiver vertex loses 2% of its light") {
    const double rule = PreprocessSettings{}.significance;
    // The rule's bound up to the float sums of the transfers it charges.
    const double bound = rule * (1.0 + 1e-3);
    for (const int cells : {1, 2, 4, 8}) {
        const double leftOut = largestShareLeftOut(everyPatchASource(cutWindowScene(cells)));
        MESSAGE("the window in " << (cells * cells) << " patch(es): at most " << leftOut
                                  << " of a vertex's light left out");
        CHECK(leftOut < bound);
    }
    for (const glm::ivec2 cut : {glm::ivec2(4, 1), glm::ivec2(16, 4), glm::ivec2(32, 8), glm::ivec2(64, 16)}) {
        const double leftOut = largestShareLeftOut(everyPatchASource(cutSkyScene(cut.x, cut.y)));
        MESSAGE("the sky in " << (cut.x * cut.y) << " patches: at most " << leftOut << " of a vertex's light left out");
        CHECK(leftOut < bound);
    }
}

TEST_CASE("differential composite: a window cut into 1, 4, 16 and 64 patches casts the same shadow, converging") {
    CompositeSettings all;
    all.passes = 0;   // a shadow map per listed source: the traversal alone decides
    std::vector<double> reference, error;
    for (const int cells : {1, 2, 4, 8}) {
        const CompositingScene scene = cutWindowScene(cells);
        const DifferentialModel m = everyPatchASource(scene);
        const PreparedObject object = prepareObject(m, scene.objects);
        const std::vector<glm::mat4> placement = placementsAt(scene.objects, 0);
        const CompositeFrame frame = compositeFrame(m, object, placement, all);
        const double ours = lightTaken(m, frame.image, frame.objectPixels);
        reference.push_back(lightTaken(m, differentialReference(m, object, placement), frame.objectPixels));
        error.push_back(std::abs(ours - reference.back()) / reference.back());
        MESSAGE("the window in " << (cells * cells) << " patch(es): " << frame.hits.sourcePatches.size()
                                  << " sources listed, light taken " << ours << ", the reference's " << reference.back()
                                  << " (error " << error.back() << ")");
    }
    for (size_t cut = 0; cut < reference.size(); ++cut) {
        // The same scene whatever the cut: the reference's strata are per patch, its light the same.
        CHECK(reference[cut] == doctest::Approx(reference[0]).epsilon(0.02));
        if (cut == 0) continue;
        // The window whole is one point light at its centre (section 8), a coarse answer; cut,
        // it must come closer to the reference, not lose its light.
        CHECK(error[cut] < error[0]);
        CHECK(error[cut] < 0.1);
    }
}
