#include "bench/peers/egl_context.h"

#include <cstdlib>
#include <cstring>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

namespace shadowlab::peers {
namespace {

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    }
    return false;
}

std::string eglFailure(const char* what) {
    char code[32];
    std::snprintf(code, sizeof code, "0x%04x", unsigned(eglGetError()));
    return std::string(what) + " failed (EGL error " + code + ")";
}

}  // namespace

EglContext::EglContext(int threads) {
    if (threads < 1) throw GlError("--threads must be >= 1");
    // llvmpipe reads LP_NUM_THREADS once, when its screen is created with the display.
    setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);

    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        throw GlError("EGL has no EGL_MESA_platform_surfaceless (is Mesa's libegl-mesa0 installed?)");
    }
    EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) throw GlError(eglFailure("eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA)"));
    display_ = display;
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) throw GlError(eglFailure("eglInitialize"));
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
        throw GlError("EGL display has no EGL_KHR_surfaceless_context");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) throw GlError(eglFailure("eglBindAPI(EGL_OPENGL_API)"));

    const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!eglChooseConfig(display, configAttributes, &config, 1, &configs) || configs < 1) {
        throw GlError(eglFailure("eglChooseConfig (an OpenGL-renderable config)"));
    }
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
    if (context == EGL_NO_CONTEXT) throw GlError(eglFailure("eglCreateContext (OpenGL 3.3 core)"));
    context_ = context;
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) throw GlError(eglFailure("eglMakeCurrent"));

    const auto text = [](GLenum name) {
        const GLubyte* s = glGetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
    };
    renderer_ = text(GL_RENDERER);
    version_ = text(GL_VERSION);
    if (renderer_.find("llvmpipe") == std::string::npos) {
        throw GlError("GL_RENDERER is \"" + renderer_ + "\", not llvmpipe: this benchmark times Mesa's llvmpipe only");
    }
}

EglContext::~EglContext() {
    if (!display_) return;
    EGLDisplay display = static_cast<EGLDisplay>(display_);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
}

}  // namespace shadowlab::peers
