#include "differential/photo_case.h"

#include <algorithm>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "differential/environment_dome.h"
#include "differential/patch_light.h"
#include "scenes/camera.h"
#include "shading/luminance.h"

namespace shadowlab {
namespace {

constexpr int kSquaresX = 10, kSquaresY = 7;
constexpr double kSquare = 0.025;

// The target's frame turned so that its front (-z) faces +y: (x, y, z) -> (x, -z, y).
glm::dmat4 worldFromBoard() {
    glm::dmat4 m(1.0);
    m[1] = glm::dvec4(0, 0, 1, 0);
    m[2] = glm::dvec4(0, -1, 0, 0);
    return m;
}

// The photograph's grey level at a world point (the mean of a 3 x 3 block around its pixel).
double greyAt(const Image8& photo, const Camera& camera, const glm::ivec2& crop, const glm::dvec3& p) {
    const glm::dvec4 clip = clipFromWorldD(camera) * glm::dvec4(p, 1.0);
    const int x = crop.x + int((clip.x / clip.w + 1.0) * 0.5 * camera.width);
    const int y = crop.y + int((1.0 - clip.y / clip.w) * 0.5 * camera.height);
    double sum = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int i = std::clamp(x + dx, 0, photo.width - 1), j = std::clamp(y + dy, 0, photo.height - 1);
            sum += photo.rgb[3 * (size_t(j) * size_t(photo.width) + size_t(i)) + 1];
        }
    }
    return sum / 9.0;
}

bool isGreyscale(const Image8& photo) {
    for (size_t k = 0; k < photo.rgb.size(); k += 3) {
        if (photo.rgb[k] != photo.rgb[k + 1] || photo.rgb[k] != photo.rgb[k + 2]) return false;
    }
    return true;
}

}  // namespace

PhotoCase compositingChessboard(const Image8& photo, const PhotoCalibration& calibration, const EnvironmentMap& light,
                                const Mesh& object) {
    if (photo.width != calibration.width || photo.height != calibration.height) {
        throw std::invalid_argument("chessboard case: the photograph's size is not the calibration's");
    }
    PhotoCase c;
    CompositingScene& scene = c.scene;
    scene.name = "chessboard";
    scene.camera = cameraOf(calibration, worldFromBoard(), c.crop, c.offAxisPixels);
    // The squares, each its own surface. A checkerboard's squares of one parity share a
    // colour: the parity whose squares are brighter in the photograph is the white one.
    double parityGrey[2] = {0.0, 0.0};
    for (int b = 0; b < kSquaresY; ++b) {
        for (int a = 0; a < kSquaresX; ++a) {
            parityGrey[(a + b) % 2] += greyAt(photo, scene.camera, c.crop,
                                              glm::dvec3(kSquare * (a - 0.5), 0.0, kSquare * (b - 0.5)));
        }
    }
    const int whiteParity = parityGrey[1] > parityGrey[0] ? 1 : 0;
    const double whiteGrey = parityGrey[whiteParity] / double((kSquaresX * kSquaresY + 1) / 2);
    for (int b = 0; b < kSquaresY; ++b) {
        for (int a = 0; a < kSquaresX; ++a) {
            const bool white = (a + b) % 2 == whiteParity;
            const double x0 = kSquare * (a - 1), z0 = kSquare * (b - 1);
            scene.surfaces.push_back({white ? "white square" : "black square", {x0, 0.0, z0 + kSquare}, {kSquare, 0, 0},
                                      {0, 0, -kSquare}, 1, 1, glm::dvec3(white ? 0.8 : 0.06), {}});
        }
    }
    // A greyscale photograph gets grey light and a grey object (the luminance of both), or
    // the shadows and the object would bring colours the camera could not have seen.
    const bool greyPhoto = isGreyscale(photo);
    for (PatchSurface& sky : environmentDome(light, 32, 8, 50.0)) {
        if (greyPhoto) sky.emitted[0] = glm::dvec3(luminance(sky.emitted[0]));
        scene.surfaces.push_back(std::move(sky));
    }
    // The exposure that gives a white square at the board's centre the photograph's white:
    // T(0.8 E / pi) = mean white grey, E from the dome (nothing occludes the board from it).
    const PatchModel model = flattenPatches(scene.surfaces);
    std::vector<glm::dvec3> radiance;
    std::vector<uint32_t> sky;
    for (uint32_t p = 0; p < model.patches.size(); ++p) {
        radiance.push_back(model.patches[p].emitted);
        if (model.patches[p].emitted != glm::dvec3(0.0)) sky.push_back(p);
    }
    const glm::dvec3 centre(0.1, 0.0, 0.06), up(0, 1, 0);
    const auto open = [](const glm::dvec3&) { return true; };
    const double gathered = gatheredRadiance(model, radiance, sky, centre, up, PatchSampling{}, 0, open).y;
    if (!(whiteGrey > 0.0)) throw std::invalid_argument("chessboard case: the photograph's white squares are black");
    const double whiteRadiance = CameraResponse{1.0, 2.2}.inverse(whiteGrey);   // exposure times L
    scene.response = {whiteRadiance / std::max(0.8 * gathered, 1e-12), 2.2};
    // The photograph's window as radiance under that response.
    for (int j = 0; j < scene.camera.height; ++j) {
        for (int i = 0; i < scene.camera.width; ++i) {
            const size_t k = 3 * (size_t(j + c.crop.y) * size_t(photo.width) + size_t(i + c.crop.x));
            scene.background.push_back(glm::vec3(float(scene.response.inverse(photo.rgb[k])),
                                                 float(scene.response.inverse(photo.rgb[k + 1])),
                                                 float(scene.response.inverse(photo.rgb[k + 2]))));
        }
    }
    SyntheticObject bunny{object, greyPhoto ? glm::dvec3(0.72) : glm::dvec3(0.75, 0.72, 0.68), {}};
    for (int k = 0; k < 5; ++k) {
        const glm::vec3 at(0.04f + 0.03f * float(k), 0.0f, 0.06f);
        bunny.path.push_back(glm::scale(glm::translate(glm::mat4(1.0f), at), glm::vec3(0.005f)));
    }
    scene.objects = {std::move(bunny)};
    return c;
}

}  // namespace shadowlab
