// Instances that move between frames: a fly-through's keyframes that place instances
// (scenes/camera_path.h) and PreparedScene::setInstanceTransforms, which places the moved
// ones again in place, the same bits as flattening the moved scene afresh, and drops only
// what derives from where they are.
#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/camera_path.h"
#include "scenes/instance_transform.h"
#include "scenes/prepared_scene.h"
#include "scenes/scene_file.h"
#include "tests/same_bits.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;

namespace {

// A ground, a fitted sphere, a row of two boxes and a sphere named twice, with the given
// "flythrough".
std::string movingScene(const std::string& flythrough) {
    return R"({"meshes": [{"name": "ground", "procedural": "grid", "size": [8, 8], "divisions": [4, 4]},
                          {"name": "ball", "procedural": "uv-sphere", "radius": 0.5, "slices": 12, "stacks": 6},
                          {"name": "box", "procedural": "box", "min": [0, 0, 0], "max": [0.5, 1, 0.5]}],
               "materials": [{"name": "white", "model": "lambert", "albedo": [0.8, 0.8, 0.8]}],
               "instances": [{"mesh": "ground", "material": "white"},
                             {"name": "ball", "mesh": "ball", "material": "white", "translate": [0, 1, 0],
                              "rotate": [0, 30, 0], "fit": {"height": 1.5, "ground": true}},
                             {"name": "box", "mesh": "box", "material": "white", "translate": [1, 0, 0],
                              "repeat": {"count": [2, 1, 1], "offset": [2, 0, 0]}},
                             {"name": "twin", "mesh": "ball", "material": "white", "translate": [-2, 1, 0]},
                             {"name": "twin", "mesh": "ball", "material": "white", "translate": [-3, 1, 0]}],
               "lights": [{"type": "directional", "direction": [1, 3, 1], "power": 3}],
               "camera": {"eye": [0, 4, 9], "target": [0, 0, 0], "fovy": 45, "width": 64, "height": 40},
               "flythrough": )" + flythrough + "}";
}

std::string keyframeWith(double time, const std::string& instances) {
    return R"({"time": )" + std::to_string(time) + R"(, "eye": [0, 4, 9], "target": [0, 0, 0], "instances": )" +
           instances + "}";
}

// The path of movingScene with the ball and the second box moved.
Scene sceneWithMovingBall() {
    return parseScene(movingScene(R"({"keyframes": [)" +
                                  keyframeWith(0, R"([{"instance": "ball", "translate": [0, 1, 0], "rotate": [0, 30, 0]},
                                             {"instance": 3, "translate": [1, 0, 0]}])") + "," +
                                  keyframeWith(2, R"([{"instance": 3, "translate": [1, 0.5, 1]},
                                             {"instance": "ball", "translate": [2, 1, -1], "rotate": [0, 90, 0],
                                              "scale": 2}])") + "]}"),
                      "moving.json");
}

// Types for PreparedScene::derived: one made from where the instances are, one not.
struct BallVertexData {
    static constexpr DependsOn kDependsOn = DependsOn::WorldGeometry;
    glm::vec3 firstBallVertex;
};
struct LooksData {
    static constexpr DependsOn kDependsOn = DependsOn::FixedContent;
    int builds;
};

void checkSameWorld(const WorldGeometry& a, const WorldGeometry& b) {
    CHECK(test::sameBytes(a.positions, b.positions));
    CHECK(test::sameBytes(a.cornerNormals, b.cornerNormals));
    CHECK(test::sameBytes(a.triangles, b.triangles));
    CHECK(test::sameBytes(a.triangleInstance, b.triangleInstance));
}

}  // namespace

TEST_CASE("keyframes place instances: the file's own transform again gives its bits, and between keyframes each field is linear") {
    const Scene scene = sceneWithMovingBall();
    const CameraPath& path = scene.flythrough;
    REQUIRE(path.instances.size() == 2);
    CHECK(path.instances[0].instance == 1);
    CHECK(path.instances[1].instance == 3);
    CHECK(path.instances[1].shift == glm::vec3(2, 0, 0));   // the second copy of the row
    // Keyframe 0 gives both their transforms from the file: fit and lattice shift are kept.
    const PathSample first = samplePath(path, 0, 5);
    REQUIRE(first.placements.size() == 2);
    for (const InstancePlacement& placement : first.placements) {
        INFO("instance ", placement.instance);
        CHECK(placement.worldFromObject == scene.instances[placement.instance].worldFromObject);
    }
    // Half way (frame 2 of 5 at t = 1): translate, rotate and scale each half way; the second
    // keyframe listed the instances in another order.
    const PathSample middle = samplePath(path, 2, 5);
    InstancePose ball{{1, 1, -0.5f}, {0, 60, 0}, glm::vec3(1.5f)};
    CHECK(middle.placements[0].worldFromObject == posedWorldFromObject(path.instances[0], ball));
    const glm::mat4 box = glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0)) *
                          translateRotateScale({{1, 0.25f, 0.5f}, {0, 0, 0}, glm::vec3(1)});
    CHECK(middle.placements[1].worldFromObject == box);
}

TEST_CASE("keyframes that place instances: every mistake names its field") {
    const auto errorOf = [](const std::string& first, const std::string& second) {
        return test::sceneErrorOf([&] {
            parseScene(movingScene(R"({"keyframes": [)" + keyframeWith(0, first) + "," + keyframeWith(1, second) + "]}"), "moving.json");
        });
    };
    const std::string ball = R"([{"instance": "ball", "translate": [0, 1, 0]}])";
    test::checkMessage(errorOf(R"([{"instance": "bal"}])", ball),
                       {"moving.json", "keyframes[0].instances[0].instance", "no instance is named \"bal\""});
    test::checkMessage(errorOf(R"([{"instance": 9}])", ball), {"keyframes[0].instances[0].instance"});
    test::checkMessage(errorOf(R"([{"instance": "twin"}])", ball), {"several instances", "give its index"});
    test::checkMessage(errorOf(ball, R"([{"instance": "ball", "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])"),
                       {"keyframes[1].instances[0].matrix", "a matrix does not"});
    test::checkMessage(errorOf(ball, R"([{"instance": 2}])"),
                       {"keyframes[1].instances[0].instance", "not in the first keyframe's"});
    test::checkMessage(errorOf(R"([{"instance": "ball"}, {"instance": 2}])", ball),
                       {"keyframes[1].instances", "misses instance \"box[0]\""});
    test::checkMessage(errorOf(R"([{"instance": "ball"}, {"instance": 1}])", ball),
                       {"keyframes[0].instances[1].instance", "twice"});
    test::checkMessage(errorOf(ball, "[]"), {"keyframes[1].instances", "at least one"});
    test::checkMessage(errorOf(ball, R"([{"instance": "ball", "scale": 0}])"), {"keyframes[1].instances[0].scale"});
    test::checkMessage(errorOf(ball, R"([{"instance": "ball", "translate": [0, 1, 0], "scale": 1e30}])"),
                       {"keyframes[1].instances[0]", "outside the world"});
    test::checkMessage(test::sceneErrorOf([&] {
                           parseScene(movingScene(R"({"keyframes": [)" + keyframeWith(0, ball) + R"(, {"time": 1,
                                      "eye": [0, 4, 9], "target": [0, 0, 0]}]})"), "moving.json");
                       }),
                       {"keyframes[1]", "instances in every keyframe or in none"});
}

TEST_CASE("moving instances re-places them in place, the same bits as flattening the moved scene") {
    const Scene scene = sceneWithMovingBall();
    PreparedScene prepared(scene);
    CHECK(prepared.geometryVersion() == 0);
    for (int frame : {3, 4, 0}) {
        const PathSample sample = samplePath(scene.flythrough, frame, 5);
        CHECK(prepared.setInstanceTransforms(sample.placements) == 2);
        Scene moved = scene;
        for (const InstancePlacement& placement : sample.placements)
            moved.instances[placement.instance].worldFromObject = placement.worldFromObject;
        checkSameWorld(prepared.world(), flatten(moved));
        CHECK(prepared.scene().instances[1].worldFromObject == moved.instances[1].worldFromObject);
    }
    CHECK(prepared.geometryVersion() == 3);
    // Back where the file put them (frame 0 is keyframe 0): the file's own world again.
    checkSameWorld(prepared.world(), flatten(scene));
    // Placing them where they are is no move.
    CHECK(prepared.setInstanceTransforms(samplePath(scene.flythrough, 0, 5).placements) == 0);
    CHECK(prepared.geometryVersion() == 3);
}

TEST_CASE("a move that cannot be made throws and changes nothing") {
    const Scene scene = sceneWithMovingBall();
    PreparedScene prepared(scene);
    const glm::mat4 shifted = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 1));
    glm::mat4 projective(1.0f);
    projective[2][3] = 0.5f;
    const glm::mat4 faraway = glm::translate(glm::mat4(1.0f), glm::vec3(1e36f, 0, 0));
    for (const glm::mat4& bad : {projective, faraway}) {
        const std::vector<InstancePlacement> placements{{1, shifted}, {2, bad}};
        CHECK_THROWS_AS(prepared.setInstanceTransforms(placements), std::invalid_argument);
    }
    const std::vector<InstancePlacement> missing{{1, shifted}, {uint32_t(scene.instances.size()), shifted}};
    CHECK_THROWS_AS(prepared.setInstanceTransforms(missing), std::invalid_argument);
    const std::vector<InstancePlacement> twice{{1, shifted}, {1, scene.instances[1].worldFromObject}};
    CHECK_THROWS_AS(prepared.setInstanceTransforms(twice), std::invalid_argument);
    CHECK(prepared.geometryVersion() == 0);
    checkSameWorld(prepared.world(), flatten(scene));
}

TEST_CASE("a move drops what derives from world geometry and keeps what does not") {
    const Scene scene = sceneWithMovingBall();
    PreparedScene prepared(scene);
    int builds = 0;
    const auto ballVertex = [&] { return BallVertexData{prepared.world().positions[prepared.world().triangles[instanceRanges(scene)[1].firstTriangle].x]}; };
    const glm::vec3 before = prepared.derived<BallVertexData>(ballVertex).firstBallVertex;
    CHECK(prepared.derived<LooksData>([&] { return LooksData{++builds}; }).builds == 1);
    const std::vector<EdgeAdjacency>* adjacency = &prepared.edgeAdjacency();
    const PathSample last = samplePath(scene.flythrough, 4, 5);
    REQUIRE(prepared.setInstanceTransforms(last.placements) == 2);
    std::optional<double> ms;
    CHECK(prepared.derived<BallVertexData>(ballVertex, &ms).firstBallVertex != before);   // built again, where it moved
    CHECK(ms.has_value());
    CHECK(prepared.derived<LooksData>([&] { return LooksData{++builds}; }, &ms).builds == 1);   // kept
    CHECK_FALSE(ms.has_value());
    CHECK(&prepared.edgeAdjacency() == adjacency);   // object space: kept
    // No move, nothing dropped.
    prepared.setInstanceTransforms(last.placements);
    CHECK(prepared.derived<BallVertexData>(ballVertex, &ms).firstBallVertex != before);
    CHECK_FALSE(ms.has_value());
}
