// A headless OpenGL 3.3 core context on Mesa's llvmpipe, through EGL's surfaceless platform
// (EGL_MESA_platform_surfaceless): no window, no X or Wayland, no GPU. Rendering goes into
// framebuffer objects only.
#pragma once

#include <stdexcept>
#include <string>

namespace shadowlab::peers {

class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class EglContext {
public:
    // Sets LP_NUM_THREADS (llvmpipe's rasterizer threads) to `threads` before the display
    // is created, since llvmpipe reads it when the screen is made. Throws GlError when EGL
    // or the context cannot be had, or when GL_RENDERER does not name llvmpipe (another
    // driver would time something else).
    explicit EglContext(int threads);
    ~EglContext();
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    const std::string& renderer() const { return renderer_; }
    const std::string& version() const { return version_; }

private:
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string renderer_, version_;
};

}  // namespace shadowlab::peers
