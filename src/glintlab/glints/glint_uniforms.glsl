// The glint material's parameters every GPU model glue (glints/**/*_gpu.glsl)
// reads, set by realtime/gpu_renderer.cpp from the GlintDesc.
#ifndef GLINTLAB_GLINTS_GLINT_UNIFORMS_GLSL
#define GLINTLAB_GLINTS_GLINT_UNIFORMS_GLSL

#include "glintlab/core/footprint.glsl"
#include "glintlab/core/view_differentials.glsl"

uniform int u_glint_ndf;  // NDF_BECKMANN / NDF_GGX
uniform vec2 u_glint_alpha;  // alpha_x, alpha_y
uniform float u_glint_log_density;
#ifdef GLINTLAB_MATERIAL_TEXTURES
// A material with textured parameters (the forward renderer's variant,
// realtime/shaders/material_textures.glsl): the names every glue reads are
// per-fragment values, resolved from the textures at the start of main();
// the uniforms stay readable through these two functions.
vec2 glint_alpha_uniform() { return u_glint_alpha; }
float glint_log_density_uniform() { return u_glint_log_density; }
vec2 g_glint_alpha;
float g_glint_log_density;
#define u_glint_alpha g_glint_alpha
#define u_glint_log_density g_glint_log_density
// The correlation of the glint NDF's slopes at the fragment: a normal map's
// and a curved surface's Σ_xy for the models that shear their target by it
// (GlintModelDescriptor::reads_slope_correlation); 0 elsewhere.
float g_glint_slope_correlation;
#else
const float g_glint_slope_correlation = 0.0f;
#endif
#ifdef GLINTLAB_GLINT_VIEW_DIFFERENTIALS
// The fragment's view differentials in the shading frame (the forward pass
// sets them before its light loops; core/view_differentials.glsl).
ViewDifferentials g_glint_view;
#endif
uniform uint u_glint_seed;
// The glint material's Fresnel (FresnelDesc: GLINT_FRESNEL_* mode of
// glint_fresnel.glsl, Schlick f0, conductor eta + i k, dielectric eta.x);
// here rather than in the forward pass, since wang2020's glue evaluates F
// inside its own M (001 Eq. 11).
uniform int u_fresnel_mode;
uniform vec3 u_fresnel_f0;
uniform vec3 u_fresnel_eta;
uniform vec3 u_fresnel_k;

#endif
