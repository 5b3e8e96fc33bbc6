// GPU glue of deliot2023's noise-texture variant (000 §6.3): the uniforms of
// the gated-Gaussian evaluations come from a 64 x 64 RG32F noise texture
// (realtime/glint_programs.cpp uploads deliot2023_noise_table() to texture
// unit 5) instead of two hash rounds. Defines the fetch function the shared
// file calls under GLINTLAB_DELIOT2023_NOISE_TEXTURE, ahead of its include.
#ifndef GLINTLAB_GLINTS_DELIOT2023_DELIOT2023_NOISE_TEXTURE_GPU_GLSL
#define GLINTLAB_GLINTS_DELIOT2023_DELIOT2023_NOISE_TEXTURE_GPU_GLSL

#define GLINTLAB_DELIOT2023_NOISE_TEXTURE 1
layout(binding = 5) uniform sampler2D u_deliot2023_noise;  // RG32F, 64 x 64
vec2 deliot2023_noise_fetch(uint cell_hash) {
    uint i = cell_hash % 4096u;
    return texelFetch(u_deliot2023_noise, ivec2(int(i % 64u), int(i / 64u)), 0).rg;
}
#include "glintlab/glints/deliot2023/deliot2023_gpu.glsl"

#endif
