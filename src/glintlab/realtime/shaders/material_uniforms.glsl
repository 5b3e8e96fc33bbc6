// The material of the shape being drawn (the CPU's MaterialDesc, scene.h),
// set by gpu_renderer.cpp set_material; shared by forward.frag.glsl and
// material_textures.glsl.
#ifndef GLINTLAB_REALTIME_MATERIAL_UNIFORMS_GLSL
#define GLINTLAB_REALTIME_MATERIAL_UNIFORMS_GLSL

uniform int u_material_type;  // GpuMaterialType
uniform vec3 u_albedo;        // diffuse, plastic, metallic-roughness (base colour)
uniform float u_metallic;     // metallic-roughness
uniform int u_ndf;            // conductor, dielectric, plastic
uniform vec2 u_alpha;
uniform vec3 u_eta;
uniform vec3 u_k;
uniform vec3 u_emission;  // sphere-light shapes (outer side)
// Glint material: colour (its Fresnel u_fresnel_* is glint_uniforms.glsl's).
uniform vec3 u_glint_color;
uniform vec3 u_glint_base_albedo;  // diffuse base under a dielectric coat (0: none)
uniform int u_glint_g2;  // GLINT_G2_*: the model's masking (glint_g2_mode, glint_bxdf.h)

#endif
