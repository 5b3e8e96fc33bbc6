// glintlab: render, validate and inspect glint models from the command line.
#include <cstdio>
#include <exception>
#include <string>

#include <fmt/format.h>

#include "commands.h"
#include "glintlab/core/error.h"

int main(int argc, char** argv) {
    CLI::App app{"glintlab: rendering and validation of glint (discrete microfacet) models"};
    app.require_subcommand(1);
    // The Python package's glintlab.__version__ is the same string.
    app.set_version_flag("--version", std::string("glintlab ") + GLINTLAB_VERSION);
    int status = 0;
    glintlab::cmd::add_render_command(app, &status);
    glintlab::cmd::add_info_command(app, &status);
    glintlab::cmd::add_validate_command(app, &status);
    glintlab::cmd::add_bench_command(app, &status);
    glintlab::cmd::add_dict_command(app, &status);
    glintlab::cmd::add_export_command(app, &status);
    glintlab::cmd::add_compare_command(app, &status);
#if GLINTLAB_WITH_GL
    glintlab::cmd::add_view_command(app, &status);
#endif
    if (argc > 1 && argv[1][0] != '-') {
        bool known = false;
        std::string names;
        for (const CLI::App* sub : app.get_subcommands({})) {
            known = known || sub->get_name() == argv[1];
            names += (names.empty() ? "" : ", ") + sub->get_name();
        }
        if (!known) {
            fmt::print(stderr, "glintlab: unknown command '{}' (commands: {}; see --help)\n",
                       argv[1], names);
            return 1;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const glintlab::Error& e) {
        fmt::print(stderr, "glintlab: error: {}\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        fmt::print(stderr, "glintlab: internal error: {}\n", e.what());
        return 2;
    }
    return status;
}
