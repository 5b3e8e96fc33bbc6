#include <embree3/rtcore.h>
#include <tbb/version.h>

#include <fmt/format.h>

#include "commands.h"
#include "glintlab/core/shader_sources.h"
#include "glintlab/glints/registry.h"
#if GLINTLAB_WITH_GL
#include "glintlab/realtime/glint_programs.h"
#endif

namespace glintlab::cmd {

void add_info_command(CLI::App& app, int* status) {
    CLI::App* sub =
        app.add_subcommand("info", "Print the version, the enabled features and the glint models");
    sub->callback([status] {
        fmt::print("glintlab {}\n", GLINTLAB_VERSION);
        fmt::print("features:\n");
        fmt::print("  cpu renderer     Embree {} + oneTBB {}.{}, integrators: direct, path\n",
                   RTC_VERSION_STRING, TBB_VERSION_MAJOR, TBB_VERSION_MINOR);
        fmt::print(
            "  image formats    read .exr (any compression), .hdr, .png, .jpg; write .exr, .png, "
            ".hdr\n");
        fmt::print("  scene shapes     quad, sphere, torus, heightfield, obj, gltf/glb\n");
        fmt::print(
            "  lights           point, directional (optional solid angle), sphere, environment\n");
        fmt::print("  shared shaders   {} .glsl files (C++ and GLSL 4.50)\n",
                   shader_sources().size());
#if GLINTLAB_WITH_GL
        fmt::print(
            "  gpu renderer     OpenGL 4.5 core: headless EGL (render --gpu, bench --gpu), GLFW "
            "viewer (view)\n");
#else
        fmt::print("  gpu renderer     not built (configured with -DGLINTLAB_WITH_GL=OFF)\n");
#endif
        fmt::print("glint models:\n");
        for (const GlintModelInfo& m : glint_models()) {
#if GLINTLAB_WITH_GL
            const char* where = gl::gpu_supports_model(m.id) ? "cpu+gpu" : "cpu";
#else
            const char* where = "cpu";
#endif
            fmt::print("  {:<14} {:<8} {}\n", m.name, where, m.description);
        }
        *status = 0;
    });
}

}  // namespace glintlab::cmd
