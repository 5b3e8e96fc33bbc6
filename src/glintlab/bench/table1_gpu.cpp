#include "glintlab/bench/table1_gpu.h"

#include <algorithm>
#include <chrono>

#include "glintlab/gl/gl_context.h"
#include "glintlab/gl/gpu_timer.h"
#include "glintlab/glints/wang2020/wang2020_gpu_passes.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/realtime/gpu_renderer.h"

namespace glintlab {
namespace {

std::string& device_name() {
    static std::string name;
    return name;
}

}  // namespace

std::vector<Table1Row> run_gpu_table(const Table1Options& options,
                                     const std::vector<std::string>& scenes,
                                     const std::vector<std::string>& models,
                                     const GpuTableScene& make_scene,
                                     const GpuTableMeasure& measure) {
    HeadlessContext context;
    device_name() = gl_description() + " (EGL " + context.platform() + ")";
    std::vector<Table1Row> rows;
    for (const std::string& scene_name : scenes) {
        for (const std::string& model : models) {
            Table1Row row;
            row.scene = scene_name;
            row.model = model;
            for (float log_density : options.log_densities) {
                const Scene scene = make_scene(scene_name, model, log_density);
                GpuRenderer renderer(scene);
                measure(renderer, scene, scene_name, model, row);
            }
            row.min_ms = *std::min_element(row.ms_per_density.begin(), row.ms_per_density.end());
            row.max_ms = *std::max_element(row.ms_per_density.begin(), row.ms_per_density.end());
            rows.push_back(std::move(row));
        }
    }
    return rows;
}

std::vector<Table1Row> run_table1_gpu(const Table1Options& options,
                                      const std::vector<std::string>& scenes,
                                      const std::vector<std::string>& models) {
    return run_gpu_table(
        options, scenes, models,
        [&](const std::string& scene_name, const std::string& model, float log_density) {
            return parse_scene(table1_scene_document(options, scene_name, model, log_density),
                               "bench:" + scene_name);
        },
        [&](GpuRenderer& renderer, const Scene& scene, const std::string&, const std::string& model,
            Table1Row& row) {
            renderer.set_model_option("deliot2023", "noise_texture", options.gpu_noise_texture);
            renderer.set_model_option("deliot2023", "stochastic_grid", options.gpu_stochastic_grid);
            // The engine baseline (docs/BENCHMARKS.md): smooth under an
            // environment = one split-sum lookup (no effect without one).
            renderer.set_model_option("smooth", "split_sum_environment", true);
            time_gpu_frames(renderer, scene, options.gpu_warmup, options.frames, row);
            // wang2020: 001 Table 3's passes (wang2020_gpu_passes.h).
            if (model == "wang2020")
                gl::time_wang2020_passes(scene, renderer.read_image(), options.frames,
                                         row.pass_ms_per_density);
        });
}

void time_gpu_frames(GpuRenderer& renderer, const Scene& scene, int warmup, int frames,
                     Table1Row& row) {
    // The first frame compiles and links the programs: timed on its own,
    // never among the frames' medians (an extra warm-up frame).
    const auto first = std::chrono::steady_clock::now();
    renderer.render(scene);
    renderer.finish();
    (void)renderer.pass_times();
    row.first_frame_ms_per_density.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - first)
            .count());
    for (int f = 0; f < warmup; ++f) {
        renderer.render(scene);
        (void)renderer.pass_times();
    }
    std::vector<double> ms, frame_ms, shadow_ms, background_ms;
    for (int f = 0; f < frames; ++f) {
        const auto t0 = std::chrono::steady_clock::now();
        renderer.render(scene);
        renderer.finish();
        frame_ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
        const GpuPassTimes t = renderer.pass_times();
        ms.push_back(t.forward_ms);
        shadow_ms.push_back(t.shadow_ms);
        background_ms.push_back(t.background_ms);
    }
    row.shadow_ms_per_density.push_back(gl::timing_stats(shadow_ms).median_ms);
    row.background_ms_per_density.push_back(gl::timing_stats(background_ms).median_ms);
    row.frame_ms_per_density.push_back(gl::timing_stats(frame_ms).median_ms);
    const gl::TimingStats s = gl::timing_stats(ms);
    row.ms_per_density.push_back(s.median_ms);
    row.p90_ms_per_density.push_back(s.p90_ms);
}

std::string gpu_bench_device() {
    return device_name();
}

}  // namespace glintlab
