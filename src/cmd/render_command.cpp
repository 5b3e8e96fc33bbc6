#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "commands.h"
#include "glintlab/core/bloom.h"
#include "glintlab/core/disk_cache.h"
#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/memory_limit.h"
#include "glintlab/render/image_check.h"
#include "glintlab/render/render_memory.h"
#include "glintlab/render/renderer.h"
#include "glintlab/render/sampling_advice.h"
#if GLINTLAB_WITH_GL
#include "glintlab/realtime/gpu_renderer.h"
#endif
#include "glintlab/loader/scene_edits.h"
#include "glintlab/loader/scene_loader.h"

namespace glintlab::cmd {
namespace {

struct RenderArgs {
    std::string scene;
    std::string output;
    std::optional<int> spp;
    std::optional<int64_t> seed;
    int threads = 0;
    std::string res;
    std::string integrator;
    std::optional<float> exposure;
    std::string memory_limit;
    bool no_cache = false;
    bool quiet = false;
    bool gpu = false;
    SceneEdits edits;  // --model, --set
};

// One side of --res: a decimal integer in [1, 16384], the whole text.
int parse_res_side(std::string_view text, const std::string& res) {
    int v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ptr != end || ec == std::errc::invalid_argument)
        fail("--res: expected WxH with W and H integers in [1, 16384], got \"{}\"", res);
    if (ec == std::errc::result_out_of_range || v < 1 || v > 16384)
        fail("--res: W and H must be in [1, 16384], got \"{}\" (\"{}\" is out of range)", res,
             text);
    return v;
}

}  // namespace

// The output files of `render -o PATH` (README "Output files"): the extension
// decides which file PATH is — ".exr": the linear EXR, the PNG preview beside
// it; ".png": the preview, the EXR beside it; none: ".exr" is appended; a
// directory (existing, or written with a trailing slash): <dir>/<scene stem>.exr
// and .png. Any other extension is an error.
RenderOutputs render_output_paths(const std::string& output, const std::string& scene_file) {
    namespace fs = std::filesystem;
    const fs::path stem = fs::path(scene_file).stem();
    fs::path exr;
    if (output.empty()) {
        exr = fs::path("out") / stem;
        exr += ".exr";
    } else {
        const fs::path out(output);
        const bool dir = output.back() == '/' || fs::is_directory(out);
        if (dir) {
            exr = out / stem;
            exr += ".exr";
        } else if (out.extension() == ".exr" || out.extension() == ".png") {
            exr = out;
            exr.replace_extension(".exr");
        } else if (out.extension().empty()) {
            exr = out;
            exr += ".exr";
        } else {
            fail(
                "-o {}: the extension decides the format: .exr (the PNG preview goes beside it), "
                ".png (the EXR goes beside it), none (.exr is appended) or a directory; got \"{}\"",
                output, out.extension().string());
        }
    }
    fs::path png = exr;
    png.replace_extension(".png");
    return {exr, png};
}

namespace {

int run_render(const RenderArgs& a) {
    // Every option is checked before the scene loads and long before the
    // render, so that a bad option never leaves half the outputs behind.
    if (a.exposure && !(std::isfinite(*a.exposure) && std::abs(*a.exposure) <= 20.0f))
        fail("--exposure: must be a finite number of stops in [-20, 20], got {}", *a.exposure);
    int res_w = 0, res_h = 0;
    if (!a.res.empty()) {
        const size_t x = a.res.find('x');
        if (x == std::string::npos)
            fail("--res: expected WxH with W and H integers in [1, 16384], got \"{}\"", a.res);
        res_w = parse_res_side(std::string_view(a.res).substr(0, x), a.res);
        res_h = parse_res_side(std::string_view(a.res).substr(x + 1), a.res);
    }
    const RenderOutputs out = render_output_paths(a.output, a.scene);
    if (a.no_cache) set_disk_cache_enabled(false);
    if (!a.memory_limit.empty()) {
        const std::optional<uint64_t> limit = parse_memory_size(a.memory_limit);
        if (!limit)
            fail(
                "--memory-limit: expected a size in bytes with an optional suffix K, M, G or T "
                "(powers of 1024, e.g. 512M, 16G), at least 1 byte, got \"{}\"",
                a.memory_limit);
        set_memory_limit(limit);
    }

    Scene scene = load_scene(a.scene, a.edits);
    // -o must not name the scene's own files (its environment map, or the
    // scene file itself): the render would overwrite its input.
    {
        std::vector<std::filesystem::path> inputs{a.scene};
        for (const Light& light : scene.lights)
            if (const auto* env = std::get_if<EnvironmentLight>(&light); env && !env->file.empty())
                inputs.push_back(env->file);
        for (const std::filesystem::path& output : {out.exr, out.png})
            for (const std::filesystem::path& input : inputs) {
                std::error_code ec;
                if (std::filesystem::equivalent(output, input, ec))
                    fail("-o {}: the output {} is the scene's input {}; choose another path",
                         a.output, output.string(), input.string());
            }
    }
    if (a.spp) scene.render.spp = *a.spp;
    if (a.seed) scene.render.seed = static_cast<uint64_t>(*a.seed);
    if (!a.integrator.empty())
        scene.render.integrator = a.integrator == "path" ? RenderSettings::Integrator::Path
                                                         : RenderSettings::Integrator::Direct;
    if (!a.res.empty()) scene.camera.width = res_w, scene.camera.height = res_h;
    if (a.exposure) scene.film.exposure = *a.exposure;

    if (!a.gpu)
        for (const std::string& advice : sampling_advice(scene))
            fmt::print(stderr, "warning: {}\n", advice);
    if (a.gpu && (a.spp || !a.integrator.empty()))
        fmt::print(stderr,
                   "warning: --gpu shades one sample at each pixel centre with direct lighting; "
                   "--spp and --integrator apply to CPU renders only and are ignored\n");
    require_memory(
        estimate_render_memory(scene, a.gpu),
        fmt::format("render of {} at {}x{}", a.scene, scene.camera.width, scene.camera.height));

    const std::filesystem::path& exr = out.exr;
    if (!exr.parent_path().empty()) {
        std::error_code ec;
        std::filesystem::create_directories(exr.parent_path(), ec);
        if (ec) fail("-o {}: cannot create the output directory: {}", exr.string(), ec.message());
    }

    const auto start = std::chrono::steady_clock::now();
#if GLINTLAB_WITH_GL
    Image image =
        a.gpu ? render_scene_gpu(scene) : render_scene(scene, RenderOptions{a.threads, a.quiet});
#else
    if (a.gpu) fail("--gpu: this glintlab was built without OpenGL (GLINTLAB_WITH_GL=OFF)");
    Image image = render_scene(scene, RenderOptions{a.threads, a.quiet});
#endif
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    require_finite_image(scene, image, fmt::format("render of {}", a.scene));
    const bool bloom = scene.film.bloom.strength > 0.0f;
    const Image preview = bloom ? apply_bloom(image, scene.film.bloom) : image;
    const std::filesystem::path& png = out.png;
    // Both or neither: a failed PNG once left the EXR behind.
    write_images(
        {{scene.film.bloom_exr ? &preview : &image, exr}, {&preview, png, scene.film.exposure}});
    if (!a.quiet)
        fmt::print("rendered {} ({}x{}, {}) in {:.2f} s -> {}, {}\n", a.scene, scene.camera.width,
                   scene.camera.height,
                   a.gpu ? std::string("OpenGL forward, 1 sample per pixel")
                         : fmt::format("{} spp, {}", scene.render.spp,
                                       scene.render.integrator == RenderSettings::Integrator::Path
                                           ? "path"
                                           : "direct"),
                   seconds, exr.string(), png.string());
    return 0;
}

}  // namespace

void add_render_command(CLI::App& app, int* status) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* sub = app.add_subcommand(
        "render", "Render a JSON scene on the CPU to EXR (linear) and a PNG preview (sRGB)");
    sub->add_option("scene", args->scene, "Scene file (JSON, see docs/SCENE_FORMAT.md)")
        ->required()
        ->check(CLI::ExistingFile);
    sub->add_option("-o,--output", args->output,
                    "Output file or directory: X.exr writes the EXR (linear) and X.png "
                    "(preview) beside it, X.png the preview and X.exr beside it, DIR/ writes "
                    "DIR/<scene>.exr and .png; default out/<scene>.exr");
    sub->add_option("--spp", args->spp, "Samples per pixel (overrides the scene)")
        ->check(CLI::Range(1, 1 << 20));
    sub->add_option("--seed", args->seed, "Random seed (overrides the scene)")
        ->check(CLI::Range(int64_t{0}, int64_t{4294967295}));
    sub->add_option("--threads", args->threads, "Worker threads (0 = all cores)")
        ->check(CLI::Range(0, 1024));
    sub->add_option("--res", args->res, "Resolution WxH (overrides the scene), e.g. 256x256");
    sub->add_option("--integrator", args->integrator, "direct or path (overrides the scene)")
        ->check(CLI::IsMember({"direct", "path"}));
    sub->add_option("--exposure", args->exposure, "PNG exposure in stops (overrides the scene)")
        ->check(FiniteRange(-20.0, 20.0));
    sub->add_option("--memory-limit", args->memory_limit,
                    "Refuse renders estimated to need more memory than this (bytes, or with a "
                    "suffix K, M, G, T; default GLINTLAB_MEMORY_LIMIT, else 8G or 3/4 of the "
                    "physical memory)")
        ->check(CLI::Validator(
            [](std::string& s) { return s.empty() ? std::string("an empty size") : std::string(); },
            "SIZE"));
    sub->add_flag("--no-cache", args->no_cache,
                  "Neither read nor write the on-disk table cache (also GLINTLAB_NO_CACHE=1; "
                  "README \"Table cache\")");
    sub->add_option("--model", args->edits.model,
                    "Switch every glint material to this glint model (glintlab info lists them)");
    // One value per occurrence (--set A --set B), so a --set never swallows
    // the scene path.
    sub->add_option("--set", args->edits.sets,
                    "POINTER=VALUE: set a value of the scene document before loading, e.g. "
                    "--set /materials/0/log_density=14 (JSON pointer, RFC 6901; VALUE is JSON "
                    "or a bare string); repeatable, applied in order after --model")
        ->allow_extra_args(false);
    sub->add_flag("-q,--quiet", args->quiet, "No progress bar or summary");
    sub->add_flag("--gpu", args->gpu,
                  "Render with the OpenGL 4.5 forward renderer, headless through EGL (one shading "
                  "sample at each pixel centre; --spp and --integrator do not apply)");
    sub->callback([args, status] { *status = run_render(*args); });
}

}  // namespace glintlab::cmd
