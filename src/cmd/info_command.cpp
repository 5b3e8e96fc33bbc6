#include <embree3/rtcore.h>
#include <tbb/version.h>

#include <fmt/format.h>

#include "commands.h"
#include "glintlab/core/shader_sources.h"
#include "glintlab/glints/registry.h"

namespace glintlab::cmd {

void add_info_command(CLI::App& app, int* status) {
    CLI::App* sub = app.add_subcommand("info", "Print the version, the enabled features and the glint models");
    sub->callback([status] {
        fmt::print("glintlab {}\n", GLINTLAB_VERSION);
        fmt::print("features:\n");
        fmt::print("  cpu renderer     Embree {} + oneTBB {}.{}, integrators: direct, path\n",
                   RTC_VERSION_STRING, TBB_VERSION_MAJOR, TBB_VERSION_MINOR);
        fmt::print("  image formats    read .exr (any compression), .hdr, .png, .jpg; write .exr, .png, .hdr\n");
        fmt::print("  scene shapes     quad, sphere, torus, heightfield, obj, gltf/glb\n");
        fmt::print("  lights           point, directional (optional solid angle), sphere, environment\n");
        fmt::print("  shared shaders   {} .glsl files (C++ and GLSL 4.50)\n", shader_sources().size());
        fmt::print("  gpu renderer     not built yet\n");
        fmt::print("glint models:\n");
        for (const GlintModelInfo& m : glint_models()) fmt::print("  {:<14} {}\n", m.name, m.description);
        *status = 0;
    });
}

}  // namespace glintlab::cmd
