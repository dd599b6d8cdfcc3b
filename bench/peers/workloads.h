// The peer workloads on llvmpipe (docs/peers.md defines each): the light pass, the camera
// prepass, the shadowed frame with 1 tap and 3x3 PCF, and z-fail stencil shadow volumes,
// each timed as the median of `runs` frames after `warmup`, every frame ending in glFinish.
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/common/timing.h"
#include "app/measure/bench_passes.h"
#include "bench/peers/gl_resources.h"
#include "bench/peers/gl_shaders.h"
#include "frame/render.h"
#include "scenes/camera.h"
#include "scenes/prepared_scene.h"
#include "shading/image_io.h"
#include "shadows/light_view.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/technique.h"
#include "shadows/volumes/infinite_projection.h"
#include "shadows/volumes/volume_extrusion.h"

namespace shadowlab::peers {


struct Options {
    std::vector<std::string> scenes = {"sphere-box", "throughput"};
    int threads = 2;
    int warmupRuns = 2;
    int runs = 15;
    int lightSize = 2048;
    int width = 0, height = 0;   // 0: the scene camera's
    std::string png;             // the first scene's shadowed frame (1 tap)
    std::string json;
    bool check = false;
};

struct Row {
    std::string scene, workload, peer;   // peer: "llvmpipe" or "cpu" (shadowlab's own code)
    int width = 0, height = 0;
    size_t triangles = 0;
    double medianMs = 0.0, minMs = 0.0;
};

// The median of `runs` runs of `work` after `warmup` runs, wall time.
inline Timing timeRuns(const Options& o, const std::function<void()>& work) {
    for (int k = 0; k < o.warmupRuns; ++k) work();
    std::vector<double> ms;
    for (int k = 0; k < o.runs; ++k) {
        const auto start = std::chrono::steady_clock::now();
        work();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return summarizeTimes(std::move(ms));
}

// A GL frame ends with glFinish, so its time is the work done, not queued.
inline Timing timeFrames(const Options& o, const std::function<void()>& frame) {
    const Timing t = timeRuns(o, [&] {
        frame();
        glFinish();
    });
    checkGl("timed frames");
    return t;
}

struct Programs {
    GLuint depthOnly = program(kVertexShader, kDepthOnlyFragment);
    GLuint shadowMap = program(kVertexShader, std::string("#version 330 core\n#define SHADOW_MAP 1\n") + kShadeFragment);
    GLuint lit = program(kVertexShader, std::string("#version 330 core\n") + kShadeFragment);
};

// A depth-only pass into `target`: depth test LESS, cleared to 1, with back faces culled or
// not and with a polygon offset or none. The shadow map's pass, as the shadow-map technique
// draws it (shadows/depth_map.cpp, first layer), culls nothing and takes the slope-scaled
// offset with shadowlab's default factor 1.5 and units 4 (shadowMapPass). GL's offset is
// factor * max|dz/dx, dz/dy| + units * r, where r, the minimum resolvable difference, is implementation-defined for
// fixed-point buffers; for a floating-point depth buffer (DEPTH_COMPONENT32F here) the GL
// spec (4.6, 14.6.5) makes it 2^(e - 23), e the exponent of the primitive's largest depth,
// which is exactly what shadowlab's rasterizer uses (raster/setup.cpp, polygonOffset): so
// units = 4 means four float steps at the triangle's depth in both.
struct DepthPass {
    bool cullBackFaces = false;
    std::optional<raster::PolygonOffset> offset;
};

inline DepthPass shadowMapPass() { return {false, polygonOffsetFor(BiasSettings{})}; }
inline DepthPass cameraPrepassPass() { return {true, std::nullopt}; }

inline void drawDepth(const Programs& p, const Mesh& scene, const DepthTarget& target, const glm::mat4& clipFromWorld,
                      const DepthPass& pass) {
    glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
    glViewport(0, 0, target.width, target.height);
    if (pass.cullBackFaces) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(GL_CCW);
    }
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    if (pass.offset) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(pass.offset->factor, pass.offset->units);
    }
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(p.depthOnly);
    setMatrix(p.depthOnly, "clipFromWorld", clipFromWorld);
    draw(scene);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
}

struct SceneGl {
    const PreparedScene& prepared;
    Mesh mesh;
    GLuint normalBuffer = 0, normalTexture = 0;
};

// Geometric normals per triangle (unit, counter-clockwise), for the shading passes.
inline void uploadNormals(SceneGl& s) {
    const WorldGeometry& w = s.prepared.world();
    std::vector<glm::vec4> normals;
    normals.reserve(w.triangles.size());
    for (const glm::uvec3& t : w.triangles) {
        const glm::vec3 a = w.positions[t.x], b = w.positions[t.y], c = w.positions[t.z];
        const glm::vec3 n = glm::cross(b - a, c - a);
        const float len = glm::length(n);
        normals.emplace_back(len > 0.0f ? n / len : glm::vec3(0.0f), 0.0f);
    }
    glGenBuffers(1, &s.normalBuffer);
    glBindBuffer(GL_TEXTURE_BUFFER, s.normalBuffer);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(normals.size() * sizeof(glm::vec4)), normals.data(), GL_STATIC_DRAW);
    glGenTextures(1, &s.normalTexture);
    glBindTexture(GL_TEXTURE_BUFFER, s.normalTexture);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, s.normalBuffer);
    checkGl("normals");
}

inline void bindShading(GLuint p, const SceneGl& s, const glm::mat4& clipFromWorld) {
    const Scene& scene = s.prepared.scene();
    glUseProgram(p);
    setMatrix(p, "clipFromWorld", clipFromWorld);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_BUFFER, s.normalTexture);
    glUniform1i(glGetUniformLocation(p, "triangleNormals"), 1);
    glUniform3fv(glGetUniformLocation(p, "eye"), 1, glm::value_ptr(scene.camera.eye));
    const glm::vec3 light = pointLightFor(scene.lights.at(0)).position;
    glUniform3fv(glGetUniformLocation(p, "lightPosition"), 1, glm::value_ptr(light));
}

class Workloads {
public:
    Workloads(const Options& o, const Programs& p, const PreparedScene& prepared)
        : o_(o), p_(p), s_{prepared, upload(prepared.world().positions, prepared.world().triangles)} {
        uploadNormals(s_);
    }

    std::vector<Row> run() {
        std::vector<Row> rows;
        rows.push_back(lightPass());
        rows.push_back(cameraPrepass());
        rows.push_back(shadowedFrame(FilterKind::Nearest));
        rows.push_back(shadowedFrame(FilterKind::Grid));
        for (Row& r : stencilVolumes()) rows.push_back(r);
        return rows;
    }

private:
    const Scene& scene() const { return s_.prepared.scene(); }
    Row row(const std::string& workload, int w, int h, const Timing& t, const std::string& peer = "llvmpipe") const {
        return {scene().name, workload, peer, w, h, s_.prepared.world().triangles.size(), t.medianMs, t.minMs};
    }

    // 1. `shadowlab bench`'s light pass, both facings, with the shadow map's polygon offset.
    Row lightPass() {
        const DepthTarget target(o_.lightSize, o_.lightSize);
        const glm::mat4 m = lightClipFromWorld(scene());
        const Timing t = timeFrames(o_, [&] { drawDepth(p_, s_.mesh, target, m, shadowMapPass()); });
        if (o_.check) requireVaried(readDepth(target), "light pass depth");
        return row("light pass", o_.lightSize, o_.lightSize, t);
    }

    // 2. `shadowlab bench`'s camera pass: depth only, back faces culled, depth LESS.
    Row cameraPrepass() {
        const Camera& c = scene().camera;
        const DepthTarget target(c.width, c.height);
        const glm::mat4 m = clipFromWorld(c);
        const Timing t = timeFrames(o_, [&] { drawDepth(p_, s_.mesh, target, m, cameraPrepassPass()); });
        if (o_.check) requireVaried(readDepth(target), "camera prepass depth");
        return row("camera prepass", c.width, c.height, t);
    }

    // 3. The shadow-map technique's frame: its fitted light view (shadowlab's own fit on
    // its G-buffer, computed once), the map drawn as above, then the camera pass (no
    // culling, as the G-buffer's) shading every fragment with the lookup.
    Row shadowedFrame(FilterKind kind) {
        const Camera& c = scene().camera;
        FilterSettings filter;
        filter.kind = kind;
        filter.gridSize = 3;
        LightFitOptions fit;
        fit.resolution = o_.lightSize;
        fit.marginTexels = kernelRadiusTexels(filter) + 1.5;   // as shadows/maps/shadow_map.cpp
        const GBuffer gbuffer = renderGBuffer(s_.prepared.world(), c, raster::bestSimdLevel());
        const LightView view = fitLightView(pointLightFor(scene().lights.at(0)), gbuffer, s_.prepared.world(), fit);
        const glm::mat4 lightMatrix(view.clipFromWorld());
        const DepthTarget map(o_.lightSize, o_.lightSize);
        const ColorTarget target(c.width, c.height);
        const glm::mat4 cameraMatrix = clipFromWorld(c);
        const Timing t = timeFrames(o_, [&] {
            drawDepth(p_, s_.mesh, map, lightMatrix, shadowMapPass());
            glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
            glViewport(0, 0, c.width, c.height);
            glDepthFunc(GL_LESS);
            glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            bindShading(p_.shadowMap, s_, cameraMatrix);
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, map.texture);
            glUniform1i(glGetUniformLocation(p_.shadowMap, "lightDepth"), 0);
            setMatrix(p_.shadowMap, "lightClipFromWorld", lightMatrix);
            glUniform1i(glGetUniformLocation(p_.shadowMap, "mapSize"), o_.lightSize);
            glUniform1i(glGetUniformLocation(p_.shadowMap, "pcfRadius"), kind == FilterKind::Grid ? 1 : 0);
            draw(s_.mesh);
        });
        const bool nearest = kind == FilterKind::Nearest;
        if (o_.check || (nearest && !o_.png.empty() && !pngWritten_)) {
            const std::vector<uint8_t> rgb = target.readRgb();
            if (o_.check) requireVaried(rgb, "shadowed frame colour");
            if (nearest && !o_.png.empty() && !pngWritten_) {
                writePng(o_.png, c.width, c.height, rgb);
                pngWritten_ = true;
            }
        }
        return row(nearest ? "shadowed frame 1 tap" : "shadowed frame 3x3 pcf", c.width, c.height, t);
    }

    // 4. z-fail stencil shadow volumes. The volume geometry is shadowlab's
    // (extrudeShadowVolume on the prepared scene's edge adjacency, caps included), built on
    // the CPU once and uploaded; its build is timed apart ("volume geometry"). Per frame:
    // a depth prepass with the infinite-far projection (no culling), the volumes with
    // two-sided stencil (back face, depth fail: +1; front face, depth fail: -1; wrapping;
    // no depth or colour writes), then the scene again where stencil == 0 and depth EQUAL,
    // lit by the light (the rest stays cleared: shadowed).
    std::vector<Row> stencilVolumes() {
        const Camera& c = scene().camera;
        const glm::dvec4 light(glm::dvec3(pointLightFor(scene().lights.at(0)).position), 1.0);
        const auto& adjacency = s_.prepared.edgeAdjacency();
        const Timing build = timeRuns(o_, [&] { extrudeShadowVolume(scene(), s_.prepared.world(), adjacency, light, true); });
        const ShadowVolume volume = extrudeShadowVolume(scene(), s_.prepared.world(), adjacency, light, true);
        const Mesh volumeMesh = upload(volume.vertices, volume.triangles);
        const ColorTarget target(c.width, c.height);
        const glm::mat4 m = clipFromWorldInfinite(c);
        const Timing t = timeFrames(o_, [&] {
            glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
            glViewport(0, 0, c.width, c.height);
            glDisable(GL_CULL_FACE);
            glEnable(GL_DEPTH_TEST);
            glDepthMask(GL_TRUE);
            glDepthFunc(GL_LESS);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glStencilMask(0xff);
            glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
            glClearDepth(1.0);
            glClearStencil(0);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
            // Prepass: depth only.
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glUseProgram(p_.depthOnly);
            setMatrix(p_.depthOnly, "clipFromWorld", m);
            draw(s_.mesh);
            // Stencil pass: z-fail, two-sided, wrapping.
            glDepthMask(GL_FALSE);
            glEnable(GL_STENCIL_TEST);
            glStencilFunc(GL_ALWAYS, 0, 0xff);
            glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
            glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
            draw(volumeMesh);
            // Final pass: lit where the stencil is 0.
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glStencilFunc(GL_EQUAL, 0, 0xff);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            glDepthFunc(GL_EQUAL);
            bindShading(p_.lit, s_, m);
            draw(s_.mesh);
            glDisable(GL_STENCIL_TEST);
            glDepthMask(GL_TRUE);
            glDepthFunc(GL_LESS);
        });
        if (o_.check) requireVaried(target.readRgb(), "stencil volumes colour");
        if (!o_.png.empty() && !volumePngWritten_) {
            std::string path = o_.png;
            const size_t dot = path.rfind(".png");
            path.insert(dot == std::string::npos ? path.size() : dot, "-volumes");
            writePng(path, c.width, c.height, target.readRgb());
            volumePngWritten_ = true;
        }
        glDeleteBuffers(1, &volumeMesh.vertices);
        glDeleteBuffers(1, &volumeMesh.indices);
        glDeleteVertexArrays(1, &volumeMesh.vao);
        Row frame = row("stencil volumes z-fail", c.width, c.height, t);
        Row geometry = row("volume geometry (cpu)", 0, 0, build, "cpu");
        geometry.triangles = volume.triangles.size();
        return {frame, geometry};
    }

    template <typename T>
    void requireVaried(const std::vector<T>& values, const char* what) const {
        if (distinctValues(values) < 2) throw GlError(scene().name + ": " + what + " is all one value");
    }

    const Options& o_;
    const Programs& p_;
    SceneGl s_;
    bool pngWritten_ = false, volumePngWritten_ = false;
};

}  // namespace shadowlab::peers
