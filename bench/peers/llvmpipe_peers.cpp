// shadowlab_peers: the workloads of `shadowlab bench` and of the shadow-map and
// shadow-volume techniques, rendered by Mesa's llvmpipe (OpenGL 3.3 core, EGL surfaceless)
// from the same world-space triangles and the same matrices, so that shadowlab's times
// have a peer measured on the same machine. docs/peers.md defines each workload.
//
// Every workload is timed as the median (and minimum) wall time of `runs` frames after
// `warmup` frames; a frame ends with glFinish, so the time is the GPU work done, not queued.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include "app/bench_passes.h"
#include "app/timing.h"
#include "bench/peers/egl_context.h"
#include "frame/render.h"
#include "scenes/camera.h"
#include "scenes/prepared_scene.h"
#include "scenes/scene_file.h"
#include "shading/image_io.h"
#include "shadows/light_view.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/technique.h"
#include "shadows/volumes/infinite_projection.h"
#include "shadows/volumes/volume_extrusion.h"

namespace shadowlab::peers {
namespace {

// ---- GL helpers -------------------------------------------------------------------------

void checkGl(const char* where) {
    const GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", unsigned(e));
        throw GlError(std::string(where) + ": GL error " + code);
    }
}

GLuint compile(GLenum kind, const std::string& source) {
    const GLuint shader = glCreateShader(kind);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        throw GlError(std::string("shader compilation: ") + log);
    }
    return shader;
}

GLuint program(const std::string& vertex, const std::string& fragment) {
    const GLuint p = glCreateProgram();
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex), fs = compile(GL_FRAGMENT_SHADER, fragment);
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glBindAttribLocation(p, 0, "position");
    glBindFragDataLocation(p, 0, "color");
    glLinkProgram(p);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetProgramInfoLog(p, sizeof log, nullptr, log);
        throw GlError(std::string("program link: ") + log);
    }
    glDeleteShader(vs);
    glDeleteShader(fs);
    return p;
}

// One vertex shader for every pass: a vec3 attribute reads as (x, y, z, 1), a vec4 one
// (the shadow volume's vertices, w = 0 at infinity) as it is. `invariant` makes the final
// pass of the volumes land on exactly the prepass's depths (depth test EQUAL).
const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec4 position;
uniform mat4 clipFromWorld;
out vec3 worldPosition;
invariant gl_Position;
void main() {
    worldPosition = position.xyz;
    gl_Position = clipFromWorld * position;
}
)";

const char* const kDepthOnlyFragment = R"(#version 330 core
void main() {}
)";

// Shading of the camera pass: the triangle's geometric normal (from a buffer texture, by
// gl_PrimitiveID), turned towards the eye as the G-buffer's; Lambert from the point light
// with V from a shadow-map lookup (SHADOW_MAP) or 1 (the volumes' pass, which only draws
// where the stencil is 0). The lookup is shadowlab's (shadows/maps/shadow_lookup.h, pcf.h):
// the receiver's window depth in the light's view against the texel it falls in, or the
// (2r+1)^2 texels around it (grid PCF, equal weights); coordinates clamp to the border; an
// empty texel (depth 1) is lit; the slope-scaled bias is in the map (polygon offset).
const char* const kShadeFragment = R"(
uniform samplerBuffer triangleNormals;
uniform vec3 eye;
uniform vec3 lightPosition;
in vec3 worldPosition;
out vec4 color;
#ifdef SHADOW_MAP
uniform sampler2D lightDepth;
uniform mat4 lightClipFromWorld;
uniform int mapSize;
uniform int pcfRadius;
float shadowMapVisibility(vec3 P) {
    vec4 c = lightClipFromWorld * vec4(P, 1.0);
    vec3 ndc = c.xyz / c.w;
    vec2 texel = (ndc.xy * 0.5 + 0.5) * float(mapSize);
    float depth = ndc.z * 0.5 + 0.5;
    ivec2 base = ivec2(floor(texel));
    float lit = 0.0;
    for (int dy = -pcfRadius; dy <= pcfRadius; ++dy) {
        for (int dx = -pcfRadius; dx <= pcfRadius; ++dx) {
            ivec2 q = clamp(base + ivec2(dx, dy), ivec2(0), ivec2(mapSize - 1));
            float stored = texelFetch(lightDepth, q, 0).r;
            lit += (stored >= 1.0 || depth <= stored) ? 1.0 : 0.0;
        }
    }
    float taps = float((2 * pcfRadius + 1) * (2 * pcfRadius + 1));
    return lit / taps;
}
#endif
void main() {
    vec3 P = worldPosition;
    vec3 N = texelFetch(triangleNormals, gl_PrimitiveID).xyz;
    if (dot(N, eye - P) < 0.0) N = -N;
    vec3 toLight = lightPosition - P;
    float cosine = dot(N, normalize(toLight));
    float V = 0.0;
    if (cosine > 0.0) {
#ifdef SHADOW_MAP
        V = shadowMapVisibility(P);
#else
        V = 1.0;
#endif
    }
    float radiance = 0.03 + 0.8 * V * max(cosine, 0.0);
    color = vec4(vec3(pow(radiance, 1.0 / 2.2)), 1.0);
}
)";

struct Mesh {
    GLuint vao = 0, vertices = 0, indices = 0;
    GLsizei indexCount = 0;
};

template <typename Vertex>
Mesh upload(const std::vector<Vertex>& vertices, const std::vector<glm::uvec3>& triangles) {
    Mesh m;
    glGenVertexArrays(1, &m.vao);
    glBindVertexArray(m.vao);
    glGenBuffers(1, &m.vertices);
    glBindBuffer(GL_ARRAY_BUFFER, m.vertices);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, GLint(sizeof(Vertex) / sizeof(float)), GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(0);
    glGenBuffers(1, &m.indices);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.indices);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(triangles.size() * sizeof(glm::uvec3)), triangles.data(),
                 GL_STATIC_DRAW);
    m.indexCount = GLsizei(triangles.size() * 3);
    glBindVertexArray(0);
    checkGl("uploading geometry");
    return m;
}

void draw(const Mesh& m) {
    glBindVertexArray(m.vao);
    glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
}

void setMatrix(GLuint p, const char* name, const glm::mat4& m) {
    glUniformMatrix4fv(glGetUniformLocation(p, name), 1, GL_FALSE, glm::value_ptr(m));
}

void checkFramebuffer(const char* what) {
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw GlError(std::string(what) + ": framebuffer incomplete");
    }
}

// A depth-only target: a DEPTH_COMPONENT32F texture (float depth, as shadowlab's buffers).
struct DepthTarget {
    GLuint fbo = 0, texture = 0;
    int width = 0, height = 0;
    DepthTarget(int w, int h) : width(w), height(h) {
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, w, h, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
        glGenFramebuffers(1, &fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture, 0);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        checkFramebuffer("depth target");
    }
};

// Colour (RGBA8) with depth and stencil (DEPTH32F_STENCIL8).
struct ColorTarget {
    GLuint fbo = 0, color = 0, depthStencil = 0;
    int width = 0, height = 0;
    ColorTarget(int w, int h) : width(w), height(h) {
        glGenRenderbuffers(1, &color);
        glBindRenderbuffer(GL_RENDERBUFFER, color);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
        glGenRenderbuffers(1, &depthStencil);
        glBindRenderbuffer(GL_RENDERBUFFER, depthStencil);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH32F_STENCIL8, w, h);
        glGenFramebuffers(1, &fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthStencil);
        checkFramebuffer("colour target");
    }
    // RGB bytes, row 0 at the top (GL's row 0 is the bottom).
    std::vector<uint8_t> readRgb() const {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        std::vector<uint8_t> rgba(size_t(width) * size_t(height) * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        std::vector<uint8_t> rgb(size_t(width) * size_t(height) * 3);
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const size_t from = (size_t(height - 1 - y) * size_t(width) + size_t(x)) * 4;
                const size_t to = (size_t(y) * size_t(width) + size_t(x)) * 3;
                for (int c = 0; c < 3; ++c) rgb[to + c] = rgba[from + c];
            }
        }
        return rgb;
    }
};

std::vector<float> readDepth(const DepthTarget& t) {
    glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
    std::vector<float> depth(size_t(t.width) * size_t(t.height));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, t.width, t.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    return depth;
}

template <typename T>
size_t distinctValues(const std::vector<T>& v) {
    return std::set<T>(v.begin(), v.end()).size();
}

// ---- the workloads ----------------------------------------------------------------------

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

Timing timeFrames(const Options& o, const std::function<void()>& frame) {
    for (int k = 0; k < o.warmupRuns; ++k) {
        frame();
        glFinish();
    }
    std::vector<double> ms;
    for (int k = 0; k < o.runs; ++k) {
        const auto start = std::chrono::steady_clock::now();
        frame();
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    checkGl("timed frames");
    return summarizeTimes(std::move(ms));
}

struct Programs {
    GLuint depthOnly = program(kVertexShader, kDepthOnlyFragment);
    GLuint shadowMap = program(kVertexShader, std::string("#version 330 core\n#define SHADOW_MAP 1\n") + kShadeFragment);
    GLuint lit = program(kVertexShader, std::string("#version 330 core\n") + kShadeFragment);
};

// The shadow map's depth pass as the shadow-map technique draws it (shadows/depth_map.cpp,
// first layer): no culling, depth test LESS, cleared to 1, slope-scaled polygon offset with
// shadowlab's default factor 1.5 and units 4. GL's offset is factor * max|dz/dx, dz/dy| +
// units * r, where r, the minimum resolvable difference, is implementation-defined for
// fixed-point buffers; for a floating-point depth buffer (DEPTH_COMPONENT32F here) the GL
// spec (4.6, 14.6.5) makes it 2^(e - 23), e the exponent of the primitive's largest depth,
// which is exactly what shadowlab's rasterizer uses (raster/setup.cpp, polygonOffset): so
// units = 4 means four float steps at the triangle's depth in both.
void drawShadowMapDepth(const Programs& p, const Mesh& scene, const DepthTarget& target, const glm::mat4& clipFromWorld) {
    const raster::PolygonOffset offset = polygonOffsetFor(BiasSettings{});
    glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
    glViewport(0, 0, target.width, target.height);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(offset.factor, offset.units);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(p.depthOnly);
    setMatrix(p.depthOnly, "clipFromWorld", clipFromWorld);
    draw(scene);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

struct SceneGl {
    const PreparedScene& prepared;
    Mesh mesh;
    GLuint normalBuffer = 0, normalTexture = 0;
};

// Geometric normals per triangle (unit, counter-clockwise), for the shading passes.
void uploadNormals(SceneGl& s) {
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

void bindShading(GLuint p, const SceneGl& s, const glm::mat4& clipFromWorld) {
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
        const Timing t = timeFrames(o_, [&] { drawShadowMapDepth(p_, s_.mesh, target, m); });
        if (o_.check) requireVaried(readDepth(target), "light pass depth");
        return row("light pass", o_.lightSize, o_.lightSize, t);
    }

    // 2. `shadowlab bench`'s camera pass: depth only, back faces culled, depth LESS.
    Row cameraPrepass() {
        const Camera& c = scene().camera;
        const DepthTarget target(c.width, c.height);
        const glm::mat4 m = clipFromWorld(c);
        const Timing t = timeFrames(o_, [&] {
            glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
            glViewport(0, 0, c.width, c.height);
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
            glFrontFace(GL_CCW);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
            glDepthMask(GL_TRUE);
            glClearDepth(1.0);
            glClear(GL_DEPTH_BUFFER_BIT);
            glUseProgram(p_.depthOnly);
            setMatrix(p_.depthOnly, "clipFromWorld", m);
            draw(s_.mesh);
        });
        glDisable(GL_CULL_FACE);
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
            drawShadowMapDepth(p_, s_.mesh, map, lightMatrix);
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
        const Timing build = timeRuns([&] { extrudeShadowVolume(scene(), s_.prepared.world(), adjacency, light, true); });
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

    Timing timeRuns(const std::function<void()>& work) const {
        for (int k = 0; k < o_.warmupRuns; ++k) work();
        std::vector<double> ms;
        for (int k = 0; k < o_.runs; ++k) {
            const auto start = std::chrono::steady_clock::now();
            work();
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        return summarizeTimes(std::move(ms));
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

std::string formatText(const std::vector<Row>& rows) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "%-11s %-24s %-9s %11s %10s %10s %9s\n", "scene", "workload", "peer", "size",
                  "triangles", "median ms", "min ms");
    out += line;
    for (const Row& r : rows) {
        const std::string size = r.width ? std::to_string(r.width) + "x" + std::to_string(r.height) : "-";
        std::snprintf(line, sizeof line, "%-11s %-24s %-9s %11s %10zu %10.2f %9.2f\n", r.scene.c_str(),
                      r.workload.c_str(), r.peer.c_str(), size.c_str(), r.triangles, r.medianMs, r.minMs);
        out += line;
    }
    return out;
}

std::string formatJson(const std::vector<Row>& rows, const Options& o, const EglContext& gl) {
    nlohmann::json j;
    j["renderer"] = gl.renderer();
    j["gl_version"] = gl.version();
    j["threads"] = o.threads;
    j["runs"] = o.runs;
    j["warmup"] = o.warmupRuns;
    j["rows"] = nlohmann::json::array();
    for (const Row& r : rows) {
        j["rows"].push_back({{"scene", r.scene}, {"workload", r.workload}, {"peer", r.peer}, {"width", r.width},
                             {"height", r.height}, {"triangles", r.triangles}, {"median_ms", r.medianMs},
                             {"min_ms", r.minMs}});
    }
    return j.dump(2) + "\n";
}

int run(const Options& o) {
    const EglContext gl(o.threads);   // sets LP_NUM_THREADS first
    std::fprintf(stderr, "shadowlab_peers: %s, %s, LP_NUM_THREADS=%d\n", gl.renderer().c_str(), gl.version().c_str(),
                 o.threads);
    const Programs programs;
    checkGl("programs");
    std::vector<Row> rows;
    for (const std::string& name : o.scenes) {
        Scene scene = loadScene(name);
        if (o.width > 0) scene.camera.width = o.width;
        if (o.height > 0) scene.camera.height = o.height;
        const PreparedScene prepared(std::move(scene));
        Workloads workloads(o, programs, prepared);
        for (Row& r : workloads.run()) rows.push_back(std::move(r));
    }
    std::fputs(formatText(rows).c_str(), stdout);
    if (!o.json.empty()) writeTextFile(o.json, formatJson(rows, o, gl));
    return 0;
}

}  // namespace
}  // namespace shadowlab::peers

int main(int argc, char** argv) {
    using namespace shadowlab::peers;
    Options o;
    CLI::App app("shadowlab's workloads on Mesa's llvmpipe (OpenGL 3.3 core, EGL surfaceless); docs/peers.md");
    app.add_option("--scenes", o.scenes, "scenes to render")->delimiter(',')->capture_default_str();
    app.add_option("--threads", o.threads, "llvmpipe threads (LP_NUM_THREADS)")->capture_default_str()->check(CLI::Range(1, 1024));
    app.add_option("--runs", o.runs, "measured frames per workload")->capture_default_str()->check(CLI::Range(1, 10000));
    app.add_option("--warmup", o.warmupRuns, "warm-up frames per workload")->capture_default_str()->check(CLI::Range(0, 1000));
    app.add_option("--light-size", o.lightSize, "texels per side of the light's pass and map")->capture_default_str()->check(CLI::Range(16, 16384));
    app.add_option("--width", o.width, "camera width (default: the scene's)")->check(CLI::Range(1, 16384));
    app.add_option("--height", o.height, "camera height (default: the scene's)")->check(CLI::Range(1, 16384));
    app.add_option("--png", o.png, "PNG of the first scene's shadowed frame (1 tap); NAME-volumes.png for the volumes");
    app.add_option("--json", o.json, "also write the rows as JSON");
    app.add_flag("--check", o.check, "fail unless every pass's depth or colour holds more than one value");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "shadowlab_peers: %s\n", e.what());
        return 1;
    }
}
