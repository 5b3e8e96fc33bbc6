#include <charconv>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "glintlab/core/error.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/realtime/viewer.h"

namespace glintlab::cmd {

void add_view_command(CLI::App& app, int* status) {
    struct Args {
        std::string scene;
        int frames = 0;
        std::string screenshot;
        std::string window_screenshot;
        std::string panel_report;
        std::string res;
        std::optional<float> exposure;
        bool no_ui = false;
        std::vector<std::string> gpu_options;
        bool dynamic_ibl = false;
    };
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand(
        "view", "Interactive OpenGL viewer: orbit camera, model switcher, live parameters, GPU ms");
    sub->add_option("scene", a->scene, "Scene file (JSON, see docs/SCENE_FORMAT.md)")
        ->required()
        ->check(CLI::ExistingFile);
    sub->add_option("--frames", a->frames, "Close after N frames (scripted use; 0 = until closed)")
        ->check(CLI::Range(0, 1000000));
    sub->add_option(
        "--screenshot", a->screenshot,
        "PNG of the rendered frame: written after the last of --frames, and by the P key "
        "(default glintlab_screenshot.png)");
    sub->add_option("--window-screenshot", a->window_screenshot,
                    "PNG of the whole window (panel included) after the last of --frames");
    sub->add_option("--panel-report", a->panel_report,
                    "JSON of the panel's rectangle and drawn items after the last of --frames "
                    "(layout tests)");
    sub->add_option("--res", a->res, "Window size WxH (overrides the scene's film)");
    sub->add_option("--exposure", a->exposure, "Exposure in stops (overrides the scene)")
        ->check(FiniteRange(-20.0, 20.0));
    sub->add_flag("--no-ui", a->no_ui, "Hide the Dear ImGui panel");
    sub->add_option("--gpu-option", a->gpu_options,
                    "Turn on a GPU option of the scene's glint models at start: OPTION or "
                    "MODEL.OPTION (repeatable; the panel's checkboxes toggle them)")
        ->allow_extra_args(false);
    sub->add_flag("--dynamic-ibl", a->dynamic_ibl,
                  "Same as --gpu-option dynamic_environment: prefilter the environment on the "
                  "GPU every frame (kneiphof2025, 003 Sec. 5)");
    sub->callback([a, status] {
        Scene scene = load_scene(a->scene);
        if (!a->res.empty()) {
            const size_t x = a->res.find('x');
            int w = 0, h = 0;
            const char* end = a->res.data() + a->res.size();
            const bool ok =
                x != std::string::npos && x > 0 &&
                std::from_chars(a->res.data(), a->res.data() + x, w).ptr == a->res.data() + x &&
                std::from_chars(a->res.data() + x + 1, end, h).ptr == end;
            if (!ok || w < 1 || h < 1 || w > 16384 || h > 16384)
                fail("--res: expected WxH with W and H in [1, 16384], got \"{}\"", a->res);
            scene.camera.width = w, scene.camera.height = h;
        }
        if (a->exposure) scene.film.exposure = *a->exposure;
        // Screenshots are PNG; any other name got PNG bytes under it.
        for (const std::string* s : {&a->screenshot, &a->window_screenshot})
            if (!s->empty() && std::filesystem::path(*s).extension() != ".png")
                fail("{}: {}: screenshots are written as PNG; give a .png file name",
                     s == &a->screenshot ? "--screenshot" : "--window-screenshot", *s);
        if (!a->window_screenshot.empty() && a->frames == 0)
            fail("--window-screenshot needs --frames N (taken after frame N)");
        if (!a->panel_report.empty() && a->frames == 0)
            fail("--panel-report needs --frames N (written after frame N)");
        ViewerOptions o;
        o.frames = a->frames;
        o.screenshot = a->screenshot;
        o.window_screenshot = a->window_screenshot;
        o.panel_report = a->panel_report;
        o.show_ui = !a->no_ui;
        o.gpu_options = a->gpu_options;
        if (a->dynamic_ibl) o.gpu_options.push_back("dynamic_environment");
        run_viewer(std::move(scene), o);
        *status = 0;
    });
}

}  // namespace glintlab::cmd
