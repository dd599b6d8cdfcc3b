// Example 1: rasterize a mesh into a depth buffer and write it as an image.
//
//   rasterize_depth OUT.png [WIDTH HEIGHT]
//
// writes OUT.png (linear depth as grey, near = white) and OUT.exr (the raw window depth, one
// float channel "depth"). No scene file is read: the meshes are made in code
// (scenes/procedural.h), so this is the rasterizer alone, as a shadow map uses it.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "raster/framebuffer.h"
#include "raster/rasterizer.h"
#include "scenes/camera.h"
#include "scenes/procedural.h"
#include "shading/image_io.h"

using namespace shadowlab;

int main(int argc, char** argv) try {
    if (argc != 2 && argc != 4) {
        std::fprintf(stderr, "usage: %s OUT.png [WIDTH HEIGHT]\n", argv[0]);
        return 2;
    }
    const std::filesystem::path out = argv[1];

    // 1. Geometry. A mesh is a list of object-space vertex positions and triangles (three
    //    vertex indices each, counter-clockwise seen from the front). A ground plane and a
    //    sphere, each placed in the world by a model matrix (worldFromObject).
    struct Object {
        Mesh mesh;
        glm::mat4 worldFromObject;
    };
    const Object objects[] = {
        {makeGrid({10.0f, 10.0f}, {8, 8}), glm::mat4(1.0f)},                                       // y = 0
        {makeUvSphere(1.0f, 48, 24), glm::translate(glm::mat4(1.0f), {0.0f, 1.0f, 0.0f})},   // resting on it
    };

    // 2. Camera. Its view and projection matrices take world space to clip space (OpenGL
    //    conventions: window depth 0 at the near plane, 1 at the far plane).
    Camera camera;
    camera.eye = {0.0f, 3.0f, 6.0f};
    camera.target = {0.0f, 0.7f, 0.0f};
    camera.width = argc == 4 ? std::atoi(argv[2]) : 640;
    camera.height = argc == 4 ? std::atoi(argv[3]) : 400;
    camera.zNear = 0.5f, camera.zFar = 20.0f;
    const glm::mat4 clipFromWorldMatrix = clipFromWorld(camera);

    // 3. Framebuffer: here a depth buffer only, cleared to 1 (the far plane).
    raster::Framebuffer framebuffer(camera.width, camera.height);

    // 4. Pipeline state: the fixed-function settings of a draw. The defaults are those of a
    //    depth pass: back faces culled (both meshes are seen from their front side), depth
    //    test "less", depth written, no colour.
    raster::PipelineState state;
    state.output = raster::FragmentOutput::DepthOnly;

    // 5. Draw calls. Each one runs the whole pipeline: vertex transform to clip space,
    //    clipping, triangle setup, binning into tiles, then per-tile coverage and depth test.
    //    The z-buffer resolves visibility, so the draw order does not matter.
    raster::Rasterizer rasterizer;   // the best SIMD level this CPU has
    for (const Object& object : objects) {
        raster::DrawCall call;
        call.vertices.positions = object.mesh.positions;
        call.triangles = object.mesh.triangles;
        call.clipFromObject = clipFromWorldMatrix * object.worldFromObject;
        rasterizer.draw(framebuffer, state, call);
    }
    const raster::RasterStats& stats = rasterizer.stats();
    std::printf("%llu triangles submitted, %llu set up, %llu fragments\n",
                (unsigned long long)stats.trianglesSubmitted, (unsigned long long)stats.trianglesSetUp,
                (unsigned long long)stats.fragments);

    // 6. Read back. depthImage() is row-major with row 0 at the top. Window depth is not
    //    linear in distance (most of [0, 1] is spent near the camera), so for people we
    //    invert the projection: NDC z = 2d - 1, view distance = 2nf / (f + n - z (f - n)).
    const std::vector<float> depth = framebuffer.depthImage();
    const float n = camera.zNear, f = camera.zFar;
    std::vector<float> distance(depth.size(), 0.0f);
    float nearest = f, farthest = n;
    for (size_t k = 0; k < depth.size(); ++k) {
        if (depth[k] >= 1.0f) continue;   // nothing drawn here
        const float z = 2.0f * depth[k] - 1.0f;
        distance[k] = 2.0f * n * f / (f + n - z * (f - n));
        nearest = std::min(nearest, distance[k]), farthest = std::max(farthest, distance[k]);
    }
    std::vector<uint8_t> rgb(depth.size() * 3, 0);   // background black
    for (size_t k = 0; k < depth.size(); ++k) {
        if (depth[k] >= 1.0f) continue;
        const float t = (distance[k] - nearest) / std::max(farthest - nearest, 1e-6f);   // 0 near, 1 far
        std::fill_n(&rgb[3 * k], 3, uint8_t(255.0f - 200.0f * t + 0.5f));
    }

    // 7. Write: a PNG to look at, and the exact floats in an OpenEXR file.
    writePng(out, camera.width, camera.height, rgb);
    ImageChannels exr;
    exr.width = camera.width, exr.height = camera.height;
    exr.set(channel::depth, depth);
    writeExr(std::filesystem::path(out).replace_extension(".exr"), exr);
    std::printf("distance %.3f .. %.3f m; wrote %s and its .exr\n", nearest, farthest, out.c_str());
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "rasterize_depth: %s\n", e.what());
    return 1;
}
