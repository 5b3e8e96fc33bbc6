// The glint material's parameters every GPU model glue (glints/**/*_gpu.glsl)
// reads, set by realtime/gpu_renderer.cpp from the GlintDesc.
#ifndef GLINTLAB_GLINTS_GLINT_UNIFORMS_GLSL
#define GLINTLAB_GLINTS_GLINT_UNIFORMS_GLSL

#include "glintlab/core/footprint.glsl"

uniform int u_glint_ndf;  // NDF_BECKMANN / NDF_GGX
uniform vec2 u_glint_alpha;  // alpha_x, alpha_y
uniform float u_glint_log_density;
uniform uint u_glint_seed;

#endif
