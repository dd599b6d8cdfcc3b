#include "scenes/gltf/gltf_camera.h"

#include <cmath>
#include <numbers>

#include "raster/fixed_point.h"
#include "scenes/camera.h"
#include "scenes/error_text.h"
#include "scenes/scene_limits.h"

namespace shadowlab {

std::optional<Camera> readNodeCamera(const GltfDocument& document, size_t node, const glm::dmat4& worldFromNode) {
    const int index = document.model.nodes[node].camera;
    if (index < 0) return std::nullopt;
    const std::string nodeField = "nodes[" + std::to_string(node) + "].camera";
    if (size_t(index) >= document.model.cameras.size())
        document.fail(nodeField, "names camera " + std::to_string(index) + ", but the file has " +
                                     std::to_string(document.model.cameras.size()));
    const tinygltf::Camera& source = document.model.cameras[size_t(index)];
    const std::string field = "cameras[" + std::to_string(index) + "]";
    if (source.type != "perspective")
        document.fail(field + ".type", inQuotes(source.type) + " is not read here (only perspective cameras)");
    const tinygltf::PerspectiveCamera& p = source.perspective;
    Camera camera;
    if (!(p.yfov > 0.0 && p.yfov < std::numbers::pi)) document.fail(field + ".perspective.yfov", "must be in (0, pi)");
    camera.fovyDeg = float(p.yfov * 180.0 / std::numbers::pi);
    if (!(p.znear > 0.0 && p.znear < 1e30)) document.fail(field + ".perspective.znear", "must be a finite number > 0");
    camera.zNear = float(p.znear);
    if (p.zfar > 0.0) {   // tinygltf reads an absent zfar as 0
        if (!(p.zfar > p.znear && p.zfar < 1e30)) document.fail(field + ".perspective.zfar", "must be finite and > znear");
        camera.zFar = float(p.zfar);
    } else {
        camera.zFar = 0.0f;   // the caller frames it to the scene
    }
    camera.height = kGltfImageHeight;
    camera.width = 1280;
    if (p.aspectRatio > 0.0) {
        const double width = std::round(p.aspectRatio * kGltfImageHeight);
        if (!(width >= 1.0 && width <= double(raster::kMaxViewport)))
            document.fail(field + ".perspective.aspectRatio", "makes an image " + std::to_string(width) +
                                                                  " pixels wide at 800 high, outside 1 to 8192");
        camera.width = int(width);
    }
    const glm::dvec3 eye(worldFromNode[3]);
    const glm::dvec3 forward(worldFromNode * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    const glm::dvec3 up(worldFromNode * glm::dvec4(0.0, 1.0, 0.0, 0.0));
    if (!(glm::length(forward) > 0.0) || !(glm::length(up) > 0.0))
        document.fail("nodes[" + std::to_string(node) + "]", "its transform leaves the camera no direction");
    camera.eye = glm::vec3(eye);
    camera.target = glm::vec3(eye + glm::normalize(forward));
    camera.up = glm::vec3(glm::normalize(up));
    if (!(std::abs(camera.eye.x) <= kMaxCoordinate && std::abs(camera.eye.y) <= kMaxCoordinate &&
          std::abs(camera.eye.z) <= kMaxCoordinate) ||
        viewFrameProblem(camera) != ViewFrameProblem::None)
        document.fail("nodes[" + std::to_string(node) + "]", "places its camera outside the world or without a view frame");
    return camera;
}

}  // namespace shadowlab
