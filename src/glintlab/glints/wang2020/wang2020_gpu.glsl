// GPU glue of wang2020 (Wang et al. 2020, 001) for the forward pass (realtime/forward_shaders.h):
// defines, from the model's shared .glsl and the uniforms set by
// glints/wang2020/wang2020_gpu.cpp,
//     vec3 glint_ndf(vec3 h, Footprint fp);  // D_P(h), RGB (glints/material.glsl)
// The model shades every light itself (GLINTLAB_GLINT_OWN_LIGHTS):
//     vec3 glint_own_light_add(vec3 wo, vec3 wi, vec3 li, Footprint fp);
//     vec3 glint_own_lights_flush(vec3 wo, Footprint fp);
//     vec3 glint_own_environment(vec3 n, vec3 o_world, Footprint fp);
// The SSBO bindings are kWang2020*Binding of glints/wang2020/wang2020_gpu.h;
// the uniforms and the functions above are wang2020_glue_common.glsl's
// (shared with the texture variant of `glintlab export`,
// wang2020_export_textures.glsl).
#ifndef GLINTLAB_GLINTS_WANG2020_WANG2020_GPU_GLSL
#define GLINTLAB_GLINTS_WANG2020_WANG2020_GPU_GLSL

// Several lights: up to four to a quadtree traversal (wang2020_tables.glsl).
#if GLINTLAB_POINT_LIGHTS + GLINTLAB_DIRECTIONAL_LIGHTS > 1
#define GLINTLAB_WANG2020_LIGHTS (GLINTLAB_POINT_LIGHTS + GLINTLAB_DIRECTIONAL_LIGHTS)
#endif

#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/glints/wang2020/wang2020_tables.glsl"
// The CPU's arrays (wang2020_gpu.cpp): DpfTable::values(),
// PrefilterTable::data(), ParticleQuadtree::nodes(),
// ParticleRadianceTable (what the micro scale's particles reflect: point values or L_γ).
layout(std430, binding = 1) readonly buffer Wang2020Dpf { float u_wang2020_dpf[]; };
layout(std430, binding = 2) readonly buffer Wang2020Prefilter { vec4 u_wang2020_prefilter[]; };
layout(std430, binding = 3) readonly buffer Wang2020Nodes { uvec2 u_wang2020_nodes[]; };
layout(std430, binding = 4) readonly buffer Wang2020Cone { vec4 u_wang2020_cone[]; };
float wang2020_dpf_value(int index) { return u_wang2020_dpf[index]; }
vec4 wang2020_prefilter_value(int index) { return u_wang2020_prefilter[index]; }
uvec2 wang2020_node(int index) { return u_wang2020_nodes[index]; }
vec4 wang2020_cone_value(int index) { return u_wang2020_cone[index]; }
#include "glintlab/glints/wang2020/wang2020_glue_common.glsl"

#endif
