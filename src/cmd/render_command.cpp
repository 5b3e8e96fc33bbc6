#include <charconv>
#include <chrono>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "commands.h"
#include "glintlab/core/bloom.h"
#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/render/renderer.h"
#if GLINTLAB_WITH_GL
#include "glintlab/realtime/gpu_renderer.h"
#endif
#include "glintlab/scene/scene_loader.h"

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
    bool quiet = false;
    bool gpu = false;
};

int run_render(const RenderArgs& a) {
    Scene scene = load_scene(a.scene);
    if (a.spp) scene.render.spp = *a.spp;
    if (a.seed) scene.render.seed = static_cast<uint64_t>(*a.seed);
    if (!a.integrator.empty())
        scene.render.integrator = a.integrator == "path" ? RenderSettings::Integrator::Path
                                                         : RenderSettings::Integrator::Direct;
    if (!a.res.empty()) {
        // WxH, both integers in [1, 16384].
        const size_t x = a.res.find('x');
        int w = 0, h = 0;
        const char* end = a.res.data() + a.res.size();
        const bool ok =
            x != std::string::npos &&
            std::from_chars(a.res.data(), a.res.data() + x, w).ptr == a.res.data() + x &&
            std::from_chars(a.res.data() + x + 1, end, h).ptr == end && x > 0 &&
            x + 1 < a.res.size();
        if (!ok) fail("--res: expected WxH with W and H in [1, 16384], got \"{}\"", a.res);
        if (w < 1 || h < 1 || w > 16384 || h > 16384)
            fail("--res: W and H must be in [1, 16384], got {}x{}", w, h);
        scene.camera.width = w, scene.camera.height = h;
    }
    if (a.exposure) scene.film.exposure = *a.exposure;

    std::filesystem::path exr = a.output;
    if (exr.empty()) exr = std::filesystem::path("out") / std::filesystem::path(a.scene).stem();
    if (exr.extension() != ".exr") exr += ".exr";
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
    const bool bloom = scene.film.bloom.strength > 0.0f;
    const Image preview = bloom ? apply_bloom(image, scene.film.bloom) : image;
    write_exr(scene.film.bloom_exr ? preview : image, exr);
    std::filesystem::path png = exr;
    png.replace_extension(".png");
    write_png(preview, png, scene.film.exposure);
    if (!a.quiet)
        fmt::print("rendered {} ({}x{}, {} spp, {}) in {:.2f} s -> {}, {}\n", a.scene,
                   scene.camera.width, scene.camera.height, scene.render.spp,
                   a.gpu                                                         ? "OpenGL forward"
                   : scene.render.integrator == RenderSettings::Integrator::Path ? "path"
                                                                                 : "direct",
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
                    "Output EXR path (the PNG preview goes beside it); default out/<scene>.exr");
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
        ->check(CLI::Range(-20.0f, 20.0f));
    sub->add_flag("-q,--quiet", args->quiet, "No progress bar or summary");
    sub->add_flag("--gpu", args->gpu,
                  "Render with the OpenGL 4.5 forward renderer, headless through EGL (one shading "
                  "sample at each pixel centre; --spp and --integrator do not apply)");
    sub->callback([args, status] { *status = run_render(*args); });
}

}  // namespace glintlab::cmd
