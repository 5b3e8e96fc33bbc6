#include "glintlab/gl/gl_context.h"

#include <dlfcn.h>
#include <link.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <fmt/format.h>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

bool has_extension(const char* list, std::string_view name) {
    if (list == nullptr) return false;
    std::string_view s(list);
    size_t pos = 0;
    while (pos < s.size()) {
        const size_t end = std::min(s.find(' ', pos), s.size());
        if (s.substr(pos, end - pos) == name) return true;
        pos = end + 1;
    }
    return false;
}

// EGL devices exposed through EGL_EXT_device_enumeration; empty when the
// client library lacks the extension.
std::vector<EGLDeviceEXT> egl_devices() {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!has_extension(client, "EGL_EXT_device_enumeration") ||
        !has_extension(client, "EGL_EXT_platform_device"))
        return {};
    EGLint count = 0;
    if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return {};
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
    if (!eglQueryDevicesEXT(count, devices.data(), &count)) return {};
    devices.resize(static_cast<size_t>(count));
    return devices;
}

bool is_software(EGLDeviceEXT device) {
    return has_extension(eglQueryDeviceStringEXT(device, EGL_EXTENSIONS),
                         "EGL_MESA_device_software");
}

// LeakSanitizer scans the memory of the modules still loaded at exit. The
// EGL vendor library unloads Mesa's driver (the *_dri.so with its LLVM) on
// eglTerminate, and two of the driver's one-time allocations (112 bytes)
// then look leaked from an "<unknown module>" that no suppression can name.
// Pinning the driver's libraries (RTLD_NODELETE) keeps them mapped until
// exit, so leak checking stays on for every allocation of ours.
void pin_gl_driver_libraries() {
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) -> int {
            const std::string_view name = info->dlpi_name != nullptr ? info->dlpi_name : "";
            constexpr std::string_view kDriverParts[] = {"_dri.so",  "libEGL_mesa", "libGLX_mesa",
                                                         "libglapi", "libLLVM",     "libgallium"};
            for (std::string_view part : kDriverParts)
                if (name.find(part) != std::string_view::npos) {
                    // A pinned extra reference, deliberately never closed.
                    (void)dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
                    break;
                }
            return 0;
        },
        nullptr);
}

// Initialises `display`; returns false (and leaves nothing open) on failure.
bool initialise(EGLDisplay display) {
    if (display == EGL_NO_DISPLAY) return false;
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) return false;
    pin_gl_driver_libraries();
    if (major < 1 || (major == 1 && minor < 4)) {
        eglTerminate(display);
        return false;
    }
    return true;
}

// Opens the first EGL device display that initialises. `why` says what was
// tried when none does (the device count, each device's EGL error), so that
// GLINTLAB_EGL_PLATFORM=device can say which step failed.
EGLDisplay open_device_display(bool hardware_only, std::string* why = nullptr) {
    const std::vector<EGLDeviceEXT> devices = egl_devices();
    std::string tried = fmt::format("{} EGL device(s) enumerated", devices.size());
    for (size_t i = 0; i < devices.size(); ++i) {
        if (hardware_only && is_software(devices[i])) continue;
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (initialise(d)) return d;
        tried += fmt::format("; device {}: {} (EGL error 0x{:04x})", i,
                             d == EGL_NO_DISPLAY ? "no display" : "eglInitialize failed",
                             static_cast<unsigned>(eglGetError()));
    }
    if (why != nullptr) *why = tried;
    return EGL_NO_DISPLAY;
}

EGLDisplay open_surfaceless_display() {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!has_extension(client, "EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
    EGLDisplay d =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    return initialise(d) ? d : EGL_NO_DISPLAY;
}

}  // namespace

EglPlatform egl_platform_from_env() {
    const char* v = std::getenv("GLINTLAB_EGL_PLATFORM");
    if (v == nullptr || *v == '\0') return EglPlatform::Auto;
    const std::string_view s(v);
    if (s == "surfaceless") return EglPlatform::Surfaceless;
    if (s == "device") return EglPlatform::Device;
    if (s == "auto") return EglPlatform::Auto;
    fail("GLINTLAB_EGL_PLATFORM=\"{}\": expected surfaceless, device or auto", s);
}

HeadlessContext::HeadlessContext(EglPlatform platform) {
    if (platform == EglPlatform::Auto) platform = egl_platform_from_env();
    if (!epoxy_has_egl())
        fail(
            "OpenGL renderer: no EGL library found (install libegl1 and a driver: Mesa "
            "libegl-mesa0 + libgl1-mesa-dri, or the NVIDIA driver)");
    EGLDisplay display = EGL_NO_DISPLAY;
    switch (platform) {
        case EglPlatform::Device: {
            std::string why;
            display = open_device_display(false, &why);
            platform_ = "device";
            if (display == EGL_NO_DISPLAY)
                fail(
                    "OpenGL renderer: GLINTLAB_EGL_PLATFORM=device but no EGL device could be "
                    "initialised (EGL_EXT_platform_device: {}); unset it to fall back to the "
                    "surfaceless platform, which Mesa and NVIDIA's EGL also provide",
                    why);
            break;
        }
        case EglPlatform::Surfaceless:
            display = open_surfaceless_display();
            platform_ = "surfaceless";
            if (display == EGL_NO_DISPLAY)
                fail(
                    "OpenGL renderer: GLINTLAB_EGL_PLATFORM=surfaceless but the EGL library has "
                    "no EGL_MESA_platform_surfaceless display (install Mesa: libegl-mesa0)");
            break;
        case EglPlatform::Auto:
            // A hardware device first, then the surfaceless platform: Mesa's
            // (llvmpipe without a GPU), and NVIDIA's EGL has one too (driver
            // 580 in a VM rendered there when its device platform would not
            // initialise; docs/BENCHMARKS.md "On an NVIDIA GPU").
            display = open_device_display(true);
            platform_ = "device";
            if (display == EGL_NO_DISPLAY) {
                display = open_surfaceless_display();
                platform_ = "surfaceless";
            }
            if (display == EGL_NO_DISPLAY)
                fail(
                    "OpenGL renderer: no EGL display (tried EGL_EXT_platform_device hardware "
                    "devices and EGL_MESA_platform_surfaceless); install a driver: Mesa "
                    "(libegl-mesa0, libgl1-mesa-dri) or NVIDIA");
            break;
    }
    display_ = display;
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        fail("OpenGL renderer: the EGL display ({}) does not support the desktop OpenGL API",
             platform_);
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    // EGL_KHR_no_config_context (Mesa, NVIDIA): no EGLConfig is needed when
    // only framebuffer objects are drawn to.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
        const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                               EGL_PBUFFER_BIT, EGL_NONE};
        EGLint n = 0;
        if (!eglChooseConfig(display, want, &config, 1, &n) || n < 1) {
            eglTerminate(display);
            fail("OpenGL renderer: the EGL display ({}) has no OpenGL config", platform_);
        }
    }
    context_ = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) {
        const EGLint error = eglGetError();
        eglTerminate(display);
        fail(
            "OpenGL renderer: the driver cannot create an OpenGL 4.5 core context through EGL "
            "({}, EGL error 0x{:x}); OpenGL 4.5 is required",
            platform_, static_cast<unsigned>(error));
    }
    make_current();
    try {
        require_gl45("OpenGL renderer (EGL " + platform_ + ")");
    } catch (...) {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context_);
        eglTerminate(display);
        throw;
    }
}

HeadlessContext::~HeadlessContext() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    // EGL displays are per process and eglTerminate is not reference
    // counted: one HeadlessContext at a time (documented in the header).
    eglTerminate(display_);
    eglReleaseThread();
}

void HeadlessContext::make_current() const {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        fail(
            "OpenGL renderer: eglMakeCurrent failed (EGL error 0x{:x}); the driver needs "
            "EGL_KHR_surfaceless_context",
            static_cast<unsigned>(eglGetError()));
}

void check_gl45(const std::string& where, int version, bool desktop, int profile_mask,
                const char* version_string) {
    if (version < 45 || !desktop || (profile_mask & GL_CONTEXT_CORE_PROFILE_BIT) == 0)
        fail("{}: OpenGL 4.5 core profile required, the driver gives \"{}\"", where,
             version_string != nullptr ? version_string : "no version");
}

void require_gl45(const std::string& where) {
    const int version = epoxy_gl_version();  // 10 * major + minor
    GLint profile = 0;
    if (version >= 32) glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    check_gl45(where, version, epoxy_is_desktop_gl() != 0, profile,
               reinterpret_cast<const char*>(glGetString(GL_VERSION)));
}

std::string gl_description() {
    const char* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    const char* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return fmt::format("OpenGL {} | {}", v != nullptr ? v : "?", r != nullptr ? r : "?");
}

}  // namespace glintlab
