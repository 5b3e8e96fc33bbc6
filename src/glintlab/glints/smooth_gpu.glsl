// GPU glue of the smooth glint material (D_P = D) for the forward pass (realtime/forward_shaders.h):
// defines, from the model's shared .glsl and the uniforms set by
// realtime/glint_programs.cpp,
//     vec3  glint_ndf(vec3 h, Footprint fp);          // D_P(h), RGB
//     float glint_masking(vec3 wo, vec3 wi, vec3 h);   // the model's G2
#ifndef GLINTLAB_GLINTS_SMOOTH_GPU_GLSL
#define GLINTLAB_GLINTS_SMOOTH_GPU_GLSL

#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/microfacet/masking.glsl"
#include "glintlab/microfacet/ndf.glsl"
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(D_Microfacet(u_glint_ndf, h, u_glint_alpha.x, u_glint_alpha.y));
}
float glint_masking(vec3 wo, vec3 wi, vec3 h) {
    return G2_SmithCorrelated(u_glint_ndf, wo, wi, u_glint_alpha.x, u_glint_alpha.y);
}

#endif
