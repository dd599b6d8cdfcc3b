// The rules of a camera and a light (scenes/view_rules.h) on values made in code, as the Python
// module makes them: each rule names the scene format's field, and a light is held only to the
// fields its type reads.
#include <cmath>
#include <limits>
#include <string>

#include <doctest/doctest.h>

#include "scenes/view_rules.h"

using namespace shadowlab;

namespace {

// The field a problem names, or "" for none.
std::string fieldOf(const std::optional<FieldProblem>& problem) { return problem ? problem->field : ""; }

Light lightOf(LightType type) {
    Light light{.type = type};
    light.radius = 0.5f;
    light.halfEdgeU = {1.0f, 0.0f, 0.0f};
    light.halfEdgeV = {0.0f, 0.0f, 1.0f};
    return light;
}

}  // namespace

TEST_CASE("the default camera and a light of each type with its fields set break no rule") {
    CHECK(!cameraProblem(Camera{}));
    for (LightType type : {LightType::Point, LightType::Spot, LightType::Directional, LightType::Disk,
                           LightType::Rectangle})
        CHECK(!lightProblem(lightOf(type)));
}

TEST_CASE("each camera rule names its field") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK(fieldOf(cameraProblem({.width = 0})) == "width");
    CHECK(fieldOf(cameraProblem({.height = 8193})) == "height");
    CHECK(fieldOf(cameraProblem({.fovyDeg = 180.0f})) == "fovy");
    CHECK(fieldOf(cameraProblem({.eye = {nan, 0.0f, 0.0f}})) == "eye");
    CHECK(fieldOf(cameraProblem({.zNear = 0.0f})) == "near");
    CHECK(fieldOf(cameraProblem({.zNear = 5.0f, .zFar = 5.0f})) == "far");
    CHECK(fieldOf(cameraProblem({.eye = {0.0f, 0.0f, 0.0f}})) == "target");
    CHECK(fieldOf(cameraProblem({.up = {0.0f, 0.0f, 0.0f}})) == "up");
    CHECK(fieldOf(cameraProblem({.eye = {0.0f, 4.0f, 0.0f}})) == "up");   // looking straight down +Y's axis
}

TEST_CASE("each light rule names its field, for the types that read it") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Light spot = lightOf(LightType::Spot);
    spot.coneAngleDeg = 95.0f;
    CHECK(fieldOf(lightProblem(spot)) == "coneAngle");
    spot.coneAngleDeg = 20.0f;
    spot.innerConeAngleDeg = 20.0f;
    CHECK(lightProblem(spot)->problem == "must be in [0, 20), got 20");
    Light disk = lightOf(LightType::Disk);
    disk.radius = -1.0f;
    CHECK(fieldOf(lightProblem(disk)) == "radius");
    disk.radius = 1.0f;
    disk.direction = {0.0f, 0.0f, 0.0f};
    CHECK(fieldOf(lightProblem(disk)) == "normal");
    Light sun = lightOf(LightType::Directional);
    sun.angularDiameterDeg = 180.0f;
    CHECK(fieldOf(lightProblem(sun)) == "angularDiameter");
    sun.angularDiameterDeg = 0.5f;
    sun.position = {nan, nan, nan};   // a sun has no position
    CHECK(!lightProblem(sun));
    Light point = lightOf(LightType::Point);
    point.position.y = nan;
    CHECK(fieldOf(lightProblem(point)) == "position");
    point.position.y = 0.0f;
    point.intensity = {1.0f, std::numeric_limits<float>::infinity(), 1.0f};
    CHECK(lightProblem(point)->problem == "color * power overflows float");
    point.intensity = {1.0f, -1.0f, 1.0f};
    CHECK(fieldOf(lightProblem(point)) == "power");
    Light rectangle = lightOf(LightType::Rectangle);
    rectangle.halfEdgeV = {1.0f, 0.5f, 0.0f};
    CHECK(lightProblem(rectangle)->problem == "must be perpendicular to halfEdgeU");
}

TEST_CASE("a direction is normalised in double and a zero or non-finite one has none") {
    const glm::vec3 tiny(1e-30f, 0.0f, 0.0f);   // its squared length underflows in float
    REQUIRE(unitDirection(tiny));
    CHECK(*unitDirection(tiny) == glm::vec3(1.0f, 0.0f, 0.0f));
    CHECK(!unitDirection(glm::vec3(0.0f)));
    CHECK(!unitDirection(glm::vec3(std::numeric_limits<float>::infinity(), 0.0f, 0.0f)));
}
