// The OpenGL pieces the peer workloads are built from: error checks, shader programs,
// meshes in buffers, depth and colour render targets, and reading a target back.
#pragma once

#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include "bench/peers/egl_context.h"

namespace shadowlab::peers {

inline void checkGl(const char* where) {
    const GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", unsigned(e));
        throw GlError(std::string(where) + ": GL error " + code);
    }
}

inline GLuint compile(GLenum kind, const std::string& source) {
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

inline GLuint program(const std::string& vertex, const std::string& fragment) {
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

struct Mesh {
    GLuint vao = 0, vertices = 0, indices = 0;
    GLsizei indexCount = 0;
};

template <typename Vertex>
inline Mesh upload(const std::vector<Vertex>& vertices, const std::vector<glm::uvec3>& triangles) {
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

inline void draw(const Mesh& m) {
    glBindVertexArray(m.vao);
    glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
}

inline void setMatrix(GLuint p, const char* name, const glm::mat4& m) {
    glUniformMatrix4fv(glGetUniformLocation(p, name), 1, GL_FALSE, glm::value_ptr(m));
}

inline void checkFramebuffer(const char* what) {
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

inline std::vector<float> readDepth(const DepthTarget& t) {
    glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
    std::vector<float> depth(size_t(t.width) * size_t(t.height));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, t.width, t.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    return depth;
}

template <typename T>
inline size_t distinctValues(const std::vector<T>& v) {
    return std::set<T>(v.begin(), v.end()).size();
}

}  // namespace shadowlab::peers
