#include <fmt/format.h>

#include "commands.h"
#include "glintlab/bench/table1.h"
#include "glintlab/core/error.h"

namespace glintlab::cmd {

void add_bench_command(CLI::App& app, int* status) {
    auto o = std::make_shared<Table1Options>();
    auto res = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    CLI::App* sub = app.add_subcommand(
        "bench", "Time every glint model on the 000 Table 1 scenes (CPU direct integrator)");
    sub->add_option("--scene", o->scenes,
                    "Scenes (default: all): PLANE_90 PLANE_25 HEIGHTMAP_90 "
                    "HEIGHTMAP_25 SPHERE MONKEY MANY (and TORUS, PEER_CHERMAIN2020)");
    sub->add_option("--model", o->models,
                    "Glint models (default: smooth deliot2023 zirr2016 chermain2020)");
    sub->add_option("--res", *res, "Resolution WxH (default 320x180)");
    sub->add_option("--frames", o->frames,
                    "Timed frames per point (median kept; default 3, 20 with --gpu)")
        ->check(CLI::Range(1, 1000));
    sub->add_option("--threads", o->threads, "Worker threads (0 = all cores)")
        ->check(CLI::Range(0, 1024));
    sub->add_flag("--json", *json, "Print one JSON object");
    sub->add_flag(
        "--gpu", o->gpu,
        "Time the OpenGL forward pass (GL_TIME_ELAPSED, headless EGL) instead of the CPU; "
        "default resolution 1920x1080");
    sub->add_flag("--noise-texture", o->gpu_noise_texture,
                  "GPU: deliot2023 with its noise texture (000 6.3) instead of the hash");
    sub->add_flag("--stochastic-grid", o->gpu_stochastic_grid,
                  "GPU: deliot2023 with its option stochastic_grid (one of the 4 grids per pixel "
                  "and frame, same mean; not the model's default)");
    sub->add_option("--log-density", o->log_densities,
                    "ln N values of the sweep (default 8 12 16 20; wang2020 needs <= 19.4)")
        ->check(FiniteRange(0.0, 40.0));
    sub->add_option("--warmup", o->gpu_warmup, "GPU: untimed frames before the timed ones")
        ->check(CLI::Range(0, 1000));
    sub->add_option("--table", o->table,
                    "Which paper's Table 1: 000 (deliot2023, default) or 003 (kneiphof2025: "
                    "IBL_STATIC IBL_DYNAMIC DIRECTIONAL x smooth wang2020_style kneiphof2025_k4 "
                    "kneiphof2025_k8; needs --gpu)")
        ->check(CLI::IsMember({"000", "003"}));
    sub->add_option("--set", o->sets,
                    "POINTER=VALUE: set a value of every row's scene document before loading "
                    "(as render --set; the 000 table's material is /materials/0); repeatable")
        ->allow_extra_args(false);
    sub->callback([o, res, json, status, sub] {
        // GPU frames are cheap: by default the median of 20 after the warm-up.
        if (o->gpu && sub->count("--frames") == 0) o->frames = 20;
        if (!res->empty()) {
            int w = 0, h = 0;
            char x = 0, extra = 0;
            if (std::sscanf(res->c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' ||
                w < 1 || h < 1 || w > 16384 || h > 16384)
                fail("--res: expected WxH with W and H in [1, 16384], got \"{}\"", *res);
            o->width = w, o->height = h;
        } else if (o->gpu) {
            o->width = 1920, o->height = 1080;  // the resolution of 000 Table 1
        }
        if (o->gpu_noise_texture && !o->gpu) fail("--noise-texture needs --gpu");
        if (o->gpu_stochastic_grid && !o->gpu) fail("--stochastic-grid needs --gpu");
        if (!o->sets.empty() && o->table == "003")
            fail("--set edits the 000 table's scenes; the 003 table builds its own");
        const auto rows = run_table1(*o);
        if (*json)
            fmt::print("{}\n", table1_to_json(*o, rows).dump(2));
        else
            fmt::print("{}", table1_to_text(*o, rows));
        *status = 0;
    });
}

}  // namespace glintlab::cmd
