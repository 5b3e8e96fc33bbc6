// `glintlab bench --gpu --table 003`: 003 Table 1 (Kneiphof & Klein 2025) on
// the OpenGL forward renderer: a full-screen glint plane lit by an
// environment map only, static (maps prefiltered once, on the CPU) and
// dynamic (prefiltered on the GPU in every frame, compute passes), and by a
// directional light for comparison; columns smooth, wang2020-style
// (kneiphof2025 K = 1 without the environment partition, 003 Fig. 8),
// K = 4 and K = 8. Same timing and JSON conventions as the 000 GPU table
// (table1_gpu.h): per density, the median forward-pass GL_TIME_ELAPSED and
// the median frame wall time (render + glFinish) over `frames` frames after
// `gpu_warmup`.
#pragma once

#include <string>
#include <vector>

#include "glintlab/bench/table1.h"

namespace glintlab {

// Rows ("scenes") and columns ("models") of 003 Table 1.
std::vector<std::string> table1_003_scene_names();  // IBL_STATIC IBL_DYNAMIC DIRECTIONAL
std::vector<std::string>
table1_003_model_names();  // smooth wang2020_style kneiphof2025_k4 kneiphof2025_k8

// The scene file of one cell at `log_density`, width x height.
nlohmann::json table1_003_scene_json(const std::string& scene, const std::string& model,
                                     float log_density, int width, int height);

// Throws glintlab::Error naming an unknown scene or model.
std::vector<Table1Row> run_table1_003_gpu(const Table1Options& options);

}  // namespace glintlab
