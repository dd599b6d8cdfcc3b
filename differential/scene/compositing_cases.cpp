#include "differential/scene/compositing_cases.h"

#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {
namespace {

PatchSurface surface(std::string name, glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, int cellsU, int cellsV,
                     glm::dvec3 reflectance, std::vector<glm::dvec3> emitted = {}) {
    return {std::move(name), origin, u, v, cellsU, cellsV, reflectance, std::move(emitted)};
}

// Every surface faces into the room. Cells are 0.25 m on the floor, which receives the
// object's shadows, and 0.5 m elsewhere.
std::vector<PatchSurface> roomSurfaces() {
    const glm::dvec3 wall(0.62, 0.6, 0.55), floor(0.45, 0.36, 0.28), wood(0.5, 0.32, 0.18);
    return {
        surface("floor", {-2, 0, 1}, {4, 0, 0}, {0, 0, -4}, 16, 16, floor),
        surface("ceiling", {-2, 2.5, -3}, {4, 0, 0}, {0, 0, 4}, 8, 8, {0.7, 0.7, 0.7}),
        surface("back wall", {-2, 0, -3}, {4, 0, 0}, {0, 2.5, 0}, 8, 5, wall),
        surface("front wall", {2, 0, 1}, {-4, 0, 0}, {0, 2.5, 0}, 8, 5, wall),
        surface("left wall", {-2, 0, 1}, {0, 0, -4}, {0, 2.5, 0}, 8, 5, wall),
        surface("right wall", {2, 0, -3}, {0, 0, 4}, {0, 2.5, 0}, 8, 5, wall),
        // The light sources: a warm ceiling panel and a window of daylight.
        surface("ceiling panel", {-0.5, 2.49, -1.8}, {1, 0, 0}, {0, 0, 0.6}, 6, 3, {0.0, 0.0, 0.0}, {{9.0, 8.2, 7.0}}),
        surface("window", {1.99, 0.9, -2.4}, {0, 0, 1.4}, {0, 1.2, 0}, 6, 4, {0.0, 0.0, 0.0}, {{6.0, 7.0, 8.5}}),
        // The desk: a top 0.75 m up on two side panels, each seen from both sides.
        surface("desk top", {-1.5, 0.75, -1.8}, {1.2, 0, 0}, {0, 0, -0.8}, 4, 3, wood),
        surface("desk underside", {-1.5, 0.73, -2.6}, {1.2, 0, 0}, {0, 0, 0.8}, 2, 2, wood),
        surface("desk left outside", {-1.52, 0, -2.6}, {0, 0, 0.8}, {0, 0.73, 0}, 2, 2, wood),
        surface("desk left inside", {-1.48, 0, -1.8}, {0, 0, -0.8}, {0, 0.73, 0}, 2, 2, wood),
        surface("desk right inside", {-0.32, 0, -2.6}, {0, 0, 0.8}, {0, 0.73, 0}, 2, 2, wood),
        surface("desk right outside", {-0.28, 0, -1.8}, {0, 0, -0.8}, {0, 0.73, 0}, 2, 2, wood),
    };
}

glm::mat4 placed(glm::vec3 at) {
    return glm::scale(glm::translate(glm::mat4(1.0f), at), glm::vec3(0.04f));
}

std::vector<glm::mat4> roomPath(RoomPath path) {
    std::vector<glm::mat4> frames;
    if (path == RoomPath::Lift) {
        for (int k = 0; k <= 6; ++k) frames.push_back(placed({0.35f, 0.1f * float(k), -1.3f}));
    } else {
        for (int k = 0; k <= 10; ++k) {
            const float t = float(k) / 10.0f;
            frames.push_back(placed({0.35f + t * (-1.25f), 0.0f, -1.3f + t * (-0.9f)}));
        }
    }
    return frames;
}

}  // namespace

CompositingScene compositingRoom(const Mesh& object, RoomPath path, int width, int height) {
    if (width < 16 || height < 16 || width > 4096 || height > 4096) {
        throw std::invalid_argument("compositing room: the image needs 16 to 4096 pixels per side");
    }
    CompositingScene scene;
    scene.name = path == RoomPath::Lift ? "room-lift" : "room";
    scene.camera.eye = {0.3f, 1.7f, 0.7f};
    scene.camera.target = {-0.3f, 0.25f, -1.8f};
    scene.camera.fovyDeg = 60.0f;
    scene.camera.width = width;
    scene.camera.height = height;
    scene.camera.zNear = 0.05f;
    scene.camera.zFar = 20.0f;
    scene.surfaces = roomSurfaces();
    scene.objects = {{object, {0.72, 0.7, 0.66}, roomPath(path)}};
    // A gamma-2.2 camera whose white is a radiance of 1.2 (the panel and window saturate).
    scene.response = {1.0 / 1.2, 2.2};
    return scene;
}

}  // namespace shadowlab
