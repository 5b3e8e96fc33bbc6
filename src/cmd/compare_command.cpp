// `glintlab compare SCENE.json`: every glint model against the explicit
// ground truth (compare/compare.h, docs/VALIDATION.md "compare").
#include <charconv>
#include <memory>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "commands.h"
#include "glintlab/compare/compare.h"
#include "glintlab/core/disk_cache.h"
#include "glintlab/core/error.h"
#include "glintlab/core/progress.h"

namespace glintlab::cmd {
namespace {

struct CompareArgs {
    compare::CompareOptions options;
    std::string models;
    std::string res;
    std::string output;
    bool json = false;
    bool quiet = false;
    bool no_cache = false;
};

int parse_side(std::string_view text, const std::string& res) {
    int v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ptr != end || ec != std::errc() || v < 1 || v > 16384)
        fail("--res: expected WxH with W and H integers in [1, 16384], got \"{}\"", res);
    return v;
}

int run_compare_command(CompareArgs& a) {
    compare::CompareOptions& o = a.options;
    if (!a.res.empty()) {
        const size_t x = a.res.find('x');
        if (x == std::string::npos)
            fail("--res: expected WxH with W and H integers in [1, 16384], got \"{}\"", a.res);
        o.width = parse_side(std::string_view(a.res).substr(0, x), a.res);
        o.height = parse_side(std::string_view(a.res).substr(x + 1), a.res);
    }
    o.models.clear();
    if (!a.models.empty()) {
        size_t start = 0;
        while (start <= a.models.size()) {
            const size_t comma = std::min(a.models.find(',', start), a.models.size());
            const std::string name = a.models.substr(start, comma - start);
            if (name.empty())
                fail("--models: expected a comma-separated list of model names or all, got \"{}\"",
                     a.models);
            o.models.push_back(name);
            start = comma + 1;
        }
    }
    if (a.no_cache) set_disk_cache_enabled(false);
    // The progress bar counts renders; it is known once the models are.
    std::unique_ptr<ProgressReporter> bar;
    o.progress = [&](int done, int total) {
        if (!bar) bar = std::make_unique<ProgressReporter>(total, "compare", a.quiet || a.json);
        bar->update(done - bar->work_done());
    };
    const compare::CompareResult result = compare::run_compare(o);
    if (bar) bar->done();
    const std::filesystem::path dir =
        a.output.empty() ? std::filesystem::path("out") / (o.scene.stem().string() + "_compare")
                         : std::filesystem::path(a.output);
    compare::write_compare_outputs(result, dir);
    if (a.json) {
        fmt::print("{}\n", result.to_json().dump(2));
    } else if (!a.quiet) {
        fmt::print("{}", result.to_text());
        fmt::print(
            "wrote {}/: grid.png, metrics.json, metrics.csv, <model>.png/.exr, "
            "<model>_diff.png, <model>_diff_blur.png\n",
            dir.string());
    }
    return 0;
}

}  // namespace

void add_compare_command(CLI::App& app, int* status) {
    auto args = std::make_shared<CompareArgs>();
    CLI::App* sub = app.add_subcommand(
        "compare",
        "Render a scene with every glint model that can shade its lights and measure each "
        "against the explicit ground truth (docs/VALIDATION.md \"compare\")");
    compare::CompareOptions& o = args->options;
    sub->add_option("scene", o.scene, "Scene file (JSON, see docs/SCENE_FORMAT.md)")
        ->required()
        ->check(CLI::ExistingFile);
    sub->add_option("--material", o.material,
                    "The glint material to switch between models (default: the first)");
    sub->add_option("--models", args->models,
                    "Comma-separated model names, or all (default); the explicit ground "
                    "truth is always rendered");
    sub->add_option("--realizations", o.realizations,
                    "Seeds per model (microstructure and sampling), for the standard errors "
                    "and the pixel variance")
        ->check(CLI::Range(2, 256));
    sub->add_option("--truth-realizations", o.truth_realizations,
                    "Seeds of the explicit ground truth (default: --realizations); more where "
                    "sparse facets reflect a small bright source (docs/VALIDATION.md)")
        ->check(CLI::Range(2, 4096));
    sub->add_option("--res", args->res, "Resolution WxH (overrides the scene), e.g. 128x128");
    sub->add_option("--spp", o.spp, "Samples per pixel of the CPU renders (overrides the scene)")
        ->check(CLI::Range(1, 1 << 20));
    sub->add_option("--frames", o.frames, "Frames of the camera path of the flicker measure")
        ->check(CLI::Range(2, 256));
    sub->add_option("--flicker-paths", o.flicker_paths,
                    "Camera paths of the flicker measure, each another realization (default 4); "
                    "the flicker is their mean, with its standard error")
        ->check(CLI::Range(1, 256));
    sub->add_option("--orbit", o.orbit_deg,
                    "Degrees the camera orbits its target over the flicker path")
        ->check(FiniteRange(1e-3, 90.0));
    sub->add_flag("!--model-extent", o.match_facet_extent,
                  "Keep every model's default facet extent (microfacet_roughness, gamma_deg) "
                  "instead of matching it to the ground truth's reflection cone "
                  "(docs/VALIDATION.md \"compare\")");
    sub->add_option("--seed", o.seed, "First seed (realization r uses seed + r)")
        ->check(CLI::Range(uint64_t{0}, uint64_t{4294967295}));
    sub->add_option("--threads", o.threads, "Worker threads (0 = all cores)")
        ->check(CLI::Range(0, 1024));
    sub->add_option("--set", o.sets,
                    "POINTER=VALUE: set a value of the scene document before loading "
                    "(as render --set); repeatable")
        ->allow_extra_args(false);
    sub->add_option("-o,--output", args->output, "Output directory (default out/<scene>_compare)");
    sub->add_flag("--gpu", o.gpu,
                  "Render the real-time models with the OpenGL renderer (headless EGL); the "
                  "ground truth stays on the CPU");
    sub->add_flag("--json", args->json, "Print metrics.json to stdout instead of the table");
    sub->add_flag("--no-cache", args->no_cache, "Neither read nor write the on-disk table cache");
    sub->add_flag("-q,--quiet", args->quiet, "No progress bar or table");
    sub->callback([args, status] { *status = run_compare_command(*args); });
}

}  // namespace glintlab::cmd
