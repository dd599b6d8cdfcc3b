// One light cut into 1, 4, 16 and 64 patches (compositing/differential/shaft_hierarchy.h;
// Gibson et al. 2003 sections 6 and 6.1): the shadow a box casts from a window onto the floor
// must not depend on how finely the window is cut. The 2% rule of section 6 judges a shaft
// by the light it carries; a window of 64 patches, each under 2% of a floor vertex's light,
// still carries the window's light, and the composite must take it off as it does for the
// window whole. Measured as the light taken off the photograph over the floor, against the
// exact differential reference of the same model.
#include <doctest/doctest.h>

#include <cmath>

#include "compositing/differential/composite.h"
#include "compositing/differential/differential_reference.h"
#include "scenes/procedural.h"
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

// The luminance an image takes off the photograph, summed over the pixels off the object.
double lightTaken(const DifferentialModel& m, const std::vector<glm::vec3>& image, const std::vector<uint8_t>& object) {
    double sum = 0.0;
    for (size_t k = 0; k < image.size(); ++k) {
        if (!object[k]) sum += double(luminance(m.background[k])) - double(luminance(image[k]));
    }
    return sum;
}

}  // namespace

TEST_CASE("differential composite: a window cut into 1, 4, 16 and 64 patches casts the same shadow, converging") {
    // Every radiant patch a source, so that the source set (section 4) chooses none of the
    // window's patches over another and only the shaft hierarchy decides what is listed.
    PreprocessSettings preprocessing;
    preprocessing.sourceShare = 1.0;
    CompositeSettings all;
    all.passes = 0;   // a shadow map per listed source: the traversal alone decides
    std::vector<double> reference, error;
    for (const int cells : {1, 2, 4, 8}) {
        const CompositingScene scene = cutWindowScene(cells);
        const DifferentialModel m = preprocess(scene, preprocessing);
        const PreparedObject object = prepareObject(m, scene.objects);
        const std::vector<glm::mat4> placement = placementsAt(scene.objects, 0);
        const CompositeFrame frame = compositeFrame(m, object, placement, all);
        const double ours = lightTaken(m, frame.image, frame.objectPixels);
        reference.push_back(lightTaken(m, differentialReference(m, object, placement), frame.objectPixels));
        error.push_back(std::abs(ours - reference.back()) / reference.back());
        MESSAGE((cells * cells) << " window patches: " << frame.hits.sourcePatches.size() << " sources listed, light "
                                << "taken " << ours << ", the reference's " << reference.back() << " (error "
                                << error.back() << ")");
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
