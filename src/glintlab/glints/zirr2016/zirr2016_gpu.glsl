// GPU glue of zirr2016 (000's baseline [ZK16]) for the forward pass (realtime/forward_shaders.h):
// defines, from the model's shared .glsl and the uniforms set by
// realtime/glint_programs.cpp (glint_model_glue_path selects this file),
//     vec3 glint_ndf(vec3 h, Footprint fp);  // D_P(h), RGB (glints/material.glsl)
#ifndef GLINTLAB_GLINTS_ZIRR2016_ZIRR2016_GPU_GLSL
#define GLINTLAB_GLINTS_ZIRR2016_ZIRR2016_GPU_GLSL

// D_P's mean where no cell can count a success (zirr2016.glsl; the CPU
// evaluates in full).
#define GLINTLAB_ZIRR2016_EXPECTATION_EXIT 1
#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/glints/zirr2016/zirr2016.glsl"
uniform float u_zirr2016_microfacet_roughness;
uniform float u_zirr2016_max_anisotropy;
uniform float u_zirr2016_screen_space_scale;
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(zirr2016_ndf(h, fp, u_glint_ndf, u_glint_alpha.x, u_glint_alpha.y,
                             g_glint_slope_correlation, u_glint_log_density, u_glint_seed, u_zirr2016_microfacet_roughness,
                             u_zirr2016_max_anisotropy, u_zirr2016_screen_space_scale));
}

#endif
