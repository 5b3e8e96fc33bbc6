// Subcommands of the `glintlab` command-line tool, each registered on the
// CLI11 app by its own file.
#pragma once

#include <cmath>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

namespace glintlab::cmd {

// A number in [min, max]. CLI::Range lets NaN through (every comparison
// with NaN is false: `view --exposure nan` failed only at the end), so
// floating-point options use this instead.
inline CLI::Validator FiniteRange(double min, double max) {
    return CLI::Validator(
        [min, max](std::string& text) -> std::string {
            double x = 0.0;
            if (!CLI::detail::lexical_cast(text, x) || !std::isfinite(x) || x < min || x > max)
                return "value " + text + " not a finite number in [" + CLI::detail::to_string(min) +
                       ", " + CLI::detail::to_string(max) + "]";
            return "";
        },
        "FLOAT in [" + CLI::detail::to_string(min) + " - " + CLI::detail::to_string(max) + "]");
}

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
