// OpenGL 4.5 core contexts for the real-time renderer (ARCHITECTURE.md "realtime/").
//  - HeadlessContext: EGL without a window. Two EGL platforms:
//      * surfaceless (EGL_MESA_platform_surfaceless): Mesa, e.g. llvmpipe in CI;
//      * device (EGL_EXT_platform_device): a GPU picked by enumeration, the
//        path the NVIDIA driver supports (it has no surfaceless platform).
//    GLINTLAB_EGL_PLATFORM=surfaceless|device forces one; otherwise a
//    hardware device (one without EGL_MESA_device_software) is preferred and
//    surfaceless is the fallback.
//  - The GLFW window of the viewer creates its own context (viewer.cpp) and
//    runs the same require_gl45() check.
// Rendering happens into framebuffer objects, so neither context needs a
// default framebuffer.
#pragma once

#include <string>

namespace glintlab {

enum class EglPlatform { Auto, Surfaceless, Device };

// One HeadlessContext at a time per process: EGL displays are shared and
// eglTerminate (in the destructor) is not reference counted.
class HeadlessContext {
  public:
    // Creates the context and makes it current on the calling thread.
    // Throws glintlab::Error when no EGL display, no OpenGL 4.5 core context
    // or a too old driver is found, naming what is missing.
    explicit HeadlessContext(EglPlatform platform = EglPlatform::Auto);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    const std::string& platform() const { return platform_; }  // "surfaceless" or "device"
    void make_current() const;

  private:
    void* display_ = nullptr;  // EGLDisplay
    void* context_ = nullptr;  // EGLContext
    std::string platform_;
};

// Throws glintlab::Error unless the current context is OpenGL >= 4.5 core
// profile; `where` names the front end in the message.
void require_gl45(const std::string& where);

// The check of require_gl45 on explicit values (testable without a driver):
// version = 10 * major + minor (epoxy_gl_version), desktop = not OpenGL ES,
// profile_mask = GL_CONTEXT_PROFILE_MASK, version_string = GL_VERSION.
void check_gl45(const std::string& where, int version, bool desktop, int profile_mask,
                const char* version_string);

// "OpenGL 4.5 (Core Profile) Mesa ... | llvmpipe (...)" of the current context.
std::string gl_description();

// Parses GLINTLAB_EGL_PLATFORM (empty/unset = Auto); throws on other values.
EglPlatform egl_platform_from_env();

}  // namespace glintlab
