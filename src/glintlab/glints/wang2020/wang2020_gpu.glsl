// GPU glue of wang2020 (papers/001) for the forward pass (realtime/forward_shaders.h):
// defines, from the model's shared .glsl and the uniforms set by
// glints/wang2020/wang2020_gpu.cpp,
//     vec3 glint_ndf(vec3 h, Footprint fp);  // D_P(h), RGB (glints/material.glsl)
// The model shades every light itself (GLINTLAB_GLINT_OWN_LIGHTS):
//     vec3 glint_own_light(vec3 wo, vec3 wi, vec3 li, Footprint fp);
//     vec3 glint_own_environment(vec3 n, vec3 o_world, Footprint fp);
// The SSBO bindings are kWang2020*Binding of glints/wang2020/wang2020_gpu.h.
#ifndef GLINTLAB_GLINTS_WANG2020_WANG2020_GPU_GLSL
#define GLINTLAB_GLINTS_WANG2020_WANG2020_GPU_GLSL

#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/glints/wang2020/wang2020_tables.glsl"
#define GLINTLAB_GLINT_OWN_LIGHTS 1
// The CPU's arrays (wang2020_gpu.cpp): DpfTable::values(),
// PrefilterTable::data(), ParticleQuadtree::nodes(),
// ConeAverageTable (the micro scale's cone-averaged environment).
layout(std430, binding = 1) readonly buffer Wang2020Dpf { float u_wang2020_dpf[]; };
layout(std430, binding = 2) readonly buffer Wang2020Prefilter { vec4 u_wang2020_prefilter[]; };
layout(std430, binding = 3) readonly buffer Wang2020Nodes { uvec2 u_wang2020_nodes[]; };
layout(std430, binding = 4) readonly buffer Wang2020Cone { vec4 u_wang2020_cone[]; };
float wang2020_dpf_value(int index) { return u_wang2020_dpf[index]; }
vec4 wang2020_prefilter_value(int index) { return u_wang2020_prefilter[index]; }
uvec2 wang2020_node(int index) { return u_wang2020_nodes[index]; }
vec4 wang2020_cone_value(int index) { return u_wang2020_cone[index]; }
uniform ivec3 u_wang2020_dpf_res;
uniform ivec4 u_wang2020_prefilter_res;
uniform int u_wang2020_depth;
uniform uint u_wang2020_seed;
uniform float u_wang2020_particles;
uniform float u_wang2020_sigma;
uniform int u_wang2020_micro;
uniform ivec2 u_wang2020_cone_res;
uniform float u_wang2020_cos_gamma;
Wang2020Tables wang2020_tables() {
    Wang2020Tables t;
    t.dpf_res = u_wang2020_dpf_res;
    t.prefilter_res = u_wang2020_prefilter_res;
    t.depth = u_wang2020_depth;
    t.seed = u_wang2020_seed;
    t.particles = u_wang2020_particles;
    t.sigma = u_wang2020_sigma;
    t.alpha = u_glint_alpha.x;
    t.micro = u_wang2020_micro;
    t.cone_res = u_wang2020_cone_res;
    t.cos_gamma = u_wang2020_cos_gamma;
    return t;
}
// Eq. 21 (the CPU's wang2020_light_radiance, untinted).
vec3 glint_own_light(vec3 wo, vec3 wi, vec3 li, Footprint fp) {
    vec2 lo, hi;
    wang2020_footprint_box(fp, lo, hi);
    return wang2020_light(wang2020_tables(), lo, hi, wi, wo, li);
}
// Eqs. 18-20 (untinted; no directional occlusion on the GPU).
vec3 glint_own_environment(vec3 n, vec3 o_world, Footprint fp) {
    vec2 lo, hi;
    wang2020_footprint_box(fp, lo, hi);
    return wang2020_environment(wang2020_tables(), lo, hi, n, o_world);
}
// The smooth Beckmann limit (the CPU GlintBxdf's wang2020 case): eval_bsdf
// needs glint_ndf, but every light of the forward pass (point, sphere as
// point, directional, environment) goes through the functions above.
#include "glintlab/glints/smooth_gpu.glsl"

#endif
