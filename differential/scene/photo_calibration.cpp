#include "differential/scene/photo_calibration.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "raster/portable_math.h"
#include "scenes/read_file.h"

namespace shadowlab {
namespace {

// Every "key numbers..." line of the file, '#' lines and blank ones skipped.
std::map<std::string, std::vector<double>> readKeyedNumbers(const std::string& path) {
    std::istringstream in(readWholeFile(path));
    std::map<std::string, std::vector<double>> lines;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key;
        if (!(words >> key) || key[0] == '#') continue;
        std::vector<double>& values = lines[key];
        values.clear();
        std::string word;
        while (words >> word) {
            try {
                size_t used = 0;
                values.push_back(std::stod(word, &used));
                if (used != word.size()) throw std::invalid_argument(word);
            } catch (const std::exception&) {
                values.clear();
                break;   // a line of text, not numbers: it cannot be a required key
            }
        }
    }
    return lines;
}

const std::vector<double>& numbers(const std::map<std::string, std::vector<double>>& lines, const std::string& key,
                                   size_t count, const std::string& path) {
    const auto it = lines.find(key);
    if (it == lines.end() || it->second.size() != count) {
        throw std::runtime_error(
            "calibration '" + path + "': needs a line '" + key + "' of " + std::to_string(count) + " numbers");
    }
    for (double v : it->second) {
        if (!std::isfinite(v))
            throw std::runtime_error("calibration '" + path + "': '" + key + "' has a non-finite number");
    }
    return it->second;
}

}  // namespace

PhotoCalibration readPhotoCalibration(const std::string& path) {
    const auto lines = readKeyedNumbers(path);
    PhotoCalibration c;
    const std::vector<double>& size = numbers(lines, "image_size", 2, path);
    const std::vector<double>& K = numbers(lines, "K", 9, path);
    const std::vector<double>& R = numbers(lines, "R", 9, path);
    const std::vector<double>& t = numbers(lines, "tvec", 3, path);
    for (const double side : size) {
        if (!(side >= 16.0 && side <= 8192.0) || side != std::floor(side)) {
            throw std::runtime_error("calibration '" + path + "': the image size must be whole, 16 to 8192 pixels");
        }
    }
    c.width = int(size[0]), c.height = int(size[1]);
    if (K[1] != 0.0 || K[3] != 0.0 || K[6] != 0.0 || K[7] != 0.0 || K[8] != 1.0 || !(K[0] > 0.0) || !(K[4] > 0.0)) {
        throw std::runtime_error(
            "calibration '" + path + "': K must be [fx 0 cx; 0 fy cy; 0 0 1] with positive focal lengths");
    }
    c.fx = K[0], c.cx = K[2], c.fy = K[4], c.cy = K[5];
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) c.R[col][row] = R[size_t(3 * row + col)];
    }
    if (!isRotation(c.R)) {
        throw std::runtime_error("calibration '" + path + "': R is not a rotation (orthonormal, determinant +1, to 1e-4)");
    }
    c.t = {t[0], t[1], t[2]};
    return c;
}

bool isRotation(const glm::dmat3& m) {
    const glm::dmat3 identity = glm::transpose(m) * m;
    for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
            if (!(std::abs(identity[a][b] - (a == b ? 1.0 : 0.0)) <= 1e-4)) return false;
        }
    }
    return glm::determinant(m) > 0.0;
}

bool isRigid(const glm::dmat4& m) {
    const bool lastRow = m[0][3] == 0.0 && m[1][3] == 0.0 && m[2][3] == 0.0 && m[3][3] == 1.0;
    return lastRow && isRotation(glm::dmat3(m));
}

Camera cameraOf(const PhotoCalibration& c, const glm::dmat4& worldFromTarget, glm::ivec2& crop, double& offAxisPixels) {
    if (!isRigid(worldFromTarget)) throw std::invalid_argument("photo camera: worldFromTarget is not rigid");
    if (std::abs(c.fx - c.fy) > 0.01 * c.fx)
        throw std::invalid_argument("photo camera: fx and fy differ (square pixels only)");
    // The principal point in our pixel coordinates (centres at whole + 0.5).
    const double px = c.cx + 0.5, py = c.cy + 0.5;
    const int halfWidth = int(std::floor(std::min(px, double(c.width) - px))) - 1;
    const int halfHeight = int(std::floor(std::min(py, double(c.height) - py))) - 1;
    if (halfWidth < 8 || halfHeight < 8)
        throw std::invalid_argument("photo camera: the principal point is too near the edge");
    crop = {int(std::lround(px - halfWidth)), int(std::lround(py - halfHeight))};
    const glm::dvec2 off(px - (crop.x + halfWidth), py - (crop.y + halfHeight));
    offAxisPixels = std::sqrt(glm::dot(off, off));
    const glm::dmat3 targetFromCamera = glm::transpose(c.R);
    const glm::dvec3 centre = -(targetFromCamera * c.t);
    const glm::dmat3 rotation(worldFromTarget);
    const glm::dvec3 eye = glm::dvec3(worldFromTarget * glm::dvec4(centre, 1.0));
    // OpenCV looks down +z with +y down the image.
    const glm::dvec3 forward = rotation * (targetFromCamera * glm::dvec3(0, 0, 1));
    const glm::dvec3 up = rotation * (targetFromCamera * glm::dvec3(0, -1, 0));
    Camera camera;
    camera.eye = glm::vec3(eye);
    camera.target = glm::vec3(eye + forward);
    camera.up = glm::vec3(up);
    camera.width = 2 * halfWidth, camera.height = 2 * halfHeight;
    camera.fovyDeg = float(2.0 * portable::atan(double(halfHeight) / c.fy) * 180.0 / std::numbers::pi);
    camera.zNear = 0.01f, camera.zFar = 100.0f;
    return camera;
}

}  // namespace shadowlab
