// `glintlab bench --gpu`: the 000 Table 1 scenes (bench/table1.h) timed on
// the OpenGL forward renderer with GL_TIME_ELAPSED queries of the forward
// pass: `gpu_warmup` frames first, then the median (and 90th percentile) of
// `frames` frames per (scene, model, density).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "glintlab/bench/table1.h"

namespace glintlab {

class GpuRenderer;
struct Scene;

std::vector<Table1Row> run_table1_gpu(const Table1Options& options,
                                      const std::vector<std::string>& scenes,
                                      const std::vector<std::string>& models);

// "OpenGL ... | renderer" of the EGL context the GPU bench uses.
std::string gpu_bench_device();

// The loop every GPU table runs (this one and table1_003_gpu.h): in one EGL
// context (recorded as gpu_bench_device()), one row per (scene, model); per
// log density a fresh GpuRenderer of make_scene(scene, model, log density),
// measured by `measure` (the table's renderer settings, time_gpu_frames and
// any extra passes); min / max of the row over the densities.
using GpuTableScene =
    std::function<Scene(const std::string& scene, const std::string& model, float log_density)>;
using GpuTableMeasure =
    std::function<void(GpuRenderer& renderer, const Scene& scene, const std::string& scene_name,
                       const std::string& model, Table1Row& row)>;
std::vector<Table1Row> run_gpu_table(const Table1Options& options,
                                     const std::vector<std::string>& scenes,
                                     const std::vector<std::string>& models,
                                     const GpuTableScene& make_scene,
                                     const GpuTableMeasure& measure);

// One density point of a GPU table: `warmup` untimed frames, then `frames`
// timed ones; appends to `row` the medians of the forward, shadow and
// background passes (GL_TIME_ELAPSED) and of the frame's wall time (render +
// glFinish), and the forward pass's 90th percentile.
void time_gpu_frames(GpuRenderer& renderer, const Scene& scene, int warmup, int frames,
                     Table1Row& row);

}  // namespace glintlab
