// GPU glue of deliot2023 with both options "noise_texture" and
// "stochastic_grid" (deliot2023_noise_texture_gpu.glsl,
// deliot2023_stochastic_gpu.glsl).
#ifndef GLINTLAB_GLINTS_DELIOT2023_DELIOT2023_NOISE_TEXTURE_STOCHASTIC_GPU_GLSL
#define GLINTLAB_GLINTS_DELIOT2023_DELIOT2023_NOISE_TEXTURE_STOCHASTIC_GPU_GLSL

#define GLINTLAB_DELIOT2023_STOCHASTIC_GRID 1
#include "glintlab/glints/deliot2023/deliot2023_noise_texture_gpu.glsl"

#endif
