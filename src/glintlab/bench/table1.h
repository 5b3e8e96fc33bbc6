// The CPU reproduction of 000 Table 1 (deliot2023's timing table): each
// benchmark scene × each glint model, rendered by the `direct` integrator
// (one evaluation per pixel per light, what a real-time shader computes) over
// a density sweep; reports the min and max time per frame over the sweep.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace glintlab {

struct Table1Options {
    std::vector<std::string> scenes;  // empty: all of table1_scene_names()
    std::vector<std::string> models;  // empty: every registered glint model
    int width = 320, height = 180;
    int frames = 3;   // timed frames per (scene, model, density); the median is kept
    int threads = 0;  // 0: all cores
    std::vector<float> log_densities = {8.0f, 12.0f, 16.0f, 20.0f};
    // OpenGL forward renderer instead of the CPU: each point is the median
    // GL_TIME_ELAPSED of the forward pass over `frames` frames after
    // `gpu_warmup` frames (realtime/gpu_bench.h).
    bool gpu = false;
    int gpu_warmup = 5;
    bool gpu_noise_texture = false;  // deliot2023 rows: the 000 §6.3 noise-texture variant
    bool gpu_stochastic_grid =
        false;  // deliot2023 rows: option stochastic_grid (one grid per pixel)
    // "000": deliot2023's Table 1 (above); "003": Kneiphof & Klein 2025's
    // Table 1 (GPU only; bench/table1_003_gpu.h: IBL static / dynamic /
    // directional rows, smooth / wang2020-style / K = 4 / K = 8 columns).
    std::string table = "000";
    // POINTER=VALUE edits of every row's scene document before loading
    // (loader/scene_edits.h apply_override_assignment; `bench --set`), e.g.
    // /materials/0/wang2020={"scale_count":"particles"} with --model wang2020.
    std::vector<std::string> sets;
};

struct Table1Row {
    std::string scene, model;
    std::vector<double> ms_per_density;  // median ms per frame, one per density
    double min_ms = 0.0, max_ms = 0.0;
    std::vector<double> p90_ms_per_density;  // GPU only: 90th percentile per density
    // GPU only: median wall-clock frame time (render + glFinish) per density;
    // the time to trust on software rasterisers whose timer queries do not
    // cover the deferred rasterisation (docs/BENCHMARKS.md).
    std::vector<double> frame_ms_per_density;
    // GPU only: the first frame's render + glFinish per density, which holds
    // the programs' compile and link (a driver's shader cache shortens it:
    // MESA_SHADER_CACHE_DISABLE=true, __GL_SHADER_DISK_CACHE=0 for a cold one).
    std::vector<double> first_frame_ms_per_density;
    // GPU only: median GL_TIME_ELAPSED of the other passes per density.
    std::vector<double> shadow_ms_per_density, background_ms_per_density;
    // GPU only, model-specific passes per density (empty for most models;
    // wang2020: 001 Table 3's passes, glints/wang2020/wang2020_gpu_passes.h).
    std::map<std::string, std::vector<double>> pass_ms_per_density;
};

// PLANE_90, PLANE_25, HEIGHTMAP_90, HEIGHTMAP_25, SPHERE, MONKEY (the
// MONKEY-like mesh: the procedural head of scene/shapes.h, 64k triangles with
// uvs; no CC0 Suzanne is available offline), MANY (a grid of 64 spheres).
// TORUS (a tessellated torus) and PEER_CHERMAIN2020 (the configuration of
// chermain2020's official viewer: sphere, point light, alpha 0.5, zeta = 2 for
// chermain2020; sweep it with --log-density 17 20 23 27) are accepted too.
std::vector<std::string> table1_scene_names();

// The scene file (JSON) of a Table 1 scene with a glint material "g" of
// `model` at `log_density`, rendered at width x height.
nlohmann::json table1_scene_json(const std::string& scene, const std::string& model,
                                 float log_density, int width, int height);

// table1_scene_json with options.sets applied (the document every row loads).
nlohmann::json table1_scene_document(const Table1Options& options, const std::string& scene,
                                     const std::string& model, float log_density);

// Throws glintlab::Error naming an unknown scene or model.
std::vector<Table1Row> run_table1(const Table1Options& options);

nlohmann::json table1_to_json(const Table1Options& options, const std::vector<Table1Row>& rows);
std::string table1_to_text(const Table1Options& options, const std::vector<Table1Row>& rows);

}  // namespace glintlab
