// Subcommands of the `glintlab` command-line tool, each registered on the
// CLI11 app by its own file.
#pragma once

#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

namespace glintlab::cmd {

// Each returns the process exit status through *status once run.
void add_render_command(CLI::App& app, int* status);
void add_info_command(CLI::App& app, int* status);
void add_validate_command(CLI::App& app, int* status);
void add_bench_command(CLI::App& app, int* status);
void add_dict_command(CLI::App& app, int* status);
void add_export_command(CLI::App& app, int* status);
void add_compare_command(CLI::App& app, int* status);
// The two files `render -o output` writes for `scene_file` (render_command.cpp).
struct RenderOutputs {
    std::filesystem::path exr, png;
};
RenderOutputs render_output_paths(const std::string& output, const std::string& scene_file);

#if GLINTLAB_WITH_GL
void add_view_command(CLI::App& app, int* status);
#endif

}  // namespace glintlab::cmd
