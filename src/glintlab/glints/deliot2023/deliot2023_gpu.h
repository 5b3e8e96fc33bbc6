// deliot2023 (000) on the GPU: the hooks of glints/gpu_model_hooks.h. The
// glue is deliot2023_gpu.glsl, or with the option "noise_texture" (000 §6.3)
// deliot2023_noise_texture_gpu.glsl, whose gated-Gaussian uniforms come from
// a 64 x 64 RG32F noise texture instead of two hash rounds.
#pragma once

#include <vector>

#include "glintlab/glints/gpu_model_hooks.h"

namespace glintlab {

inline constexpr int kDeliot2023NoiseUnit = kFirstModelTextureUnit + 1;  // binding = 5 in the glue

// The 64 x 64 uniform pairs of the noise texture, row-major, flattened:
// deliot2023_noise_table(), the CPU's own table.
std::vector<float> deliot2023_noise_pairs();

const GpuModelHooks& deliot2023_gpu_hooks();

}  // namespace glintlab
