// GPU glue of the smooth glint material (D_P = D) for the forward pass (realtime/forward_shaders.h):
// defines, from the model's shared .glsl and the uniforms set by
// realtime/glint_programs.cpp (glint_model_glue_path selects this file),
//     vec3 glint_ndf(vec3 h, Footprint fp);  // D_P(h), RGB (glints/material.glsl)
// D sheared by a footprint's slope correlation (GlintDesc::slope_correlation).
#ifndef GLINTLAB_GLINTS_SMOOTH_GPU_GLSL
#define GLINTLAB_GLINTS_SMOOTH_GPU_GLSL

#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/microfacet/ndf.glsl"
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(D_Microfacet_correlated(u_glint_ndf, h, u_glint_alpha.x, u_glint_alpha.y,
                                        g_glint_slope_correlation));
}

#endif
