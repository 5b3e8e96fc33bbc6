// GPU glue of kneiphof2025 (Kneiphof & Klein 2025, 003) for the forward pass
// (realtime/forward_shaders.h):
// defines, from the model's shared .glsl and the uniforms set by
// realtime/glint_programs.cpp and glints/kneiphof2025/kneiphof2025_gpu.cpp,
//     vec3 glint_ndf(vec3 h, Footprint fp);  // D_P(h), RGB (glints/material.glsl)
// The shared file's GLSL fetch functions read the CPU-prefiltered maps
// bound by glints/kneiphof2025/kneiphof2025_gpu.h. Point and delta directional
// lights: deliot2023's D_P with the reused grid parameters (003 Table 1:
// "identical to [DB23]"; kneiphof2025.cpp kneiphof2025_footprint_ndf).
// The environment and the area lights (sphere lights, sun cones) are
// shaded by the model itself, as kneiphof2025.cpp light_radiance does at
// the CPU's first hit: the forward shader calls glint_environment /
// glint_area_light since this glue defines GLINTLAB_GLINT_SHADES_ENVIRONMENT /
// GLINTLAB_GLINT_SHADES_AREA_LIGHTS.
#ifndef GLINTLAB_GLINTS_KNEIPHOF2025_KNEIPHOF2025_GPU_GLSL
#define GLINTLAB_GLINTS_KNEIPHOF2025_KNEIPHOF2025_GPU_GLSL

// D_P's expectation where the counts cannot differ from it in fp32
// (deliot2023.glsl deliot2023_expectation_exit; the CPU evaluates in full).
#define GLINTLAB_DELIOT2023_EXPECTATION_EXITS 1
// The half-vector-free part of D_P once per footprint, not once per light
// (deliot2023.glsl deliot2023_cached_pixel_part).
#define GLINTLAB_DELIOT2023_PIXEL_CACHE 1
#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/glints/kneiphof2025/kneiphof2025.glsl"
uniform int u_kneiphof2025_levels;         // K
uniform vec4 u_kneiphof2025_levels_a;      // L^(1..4) (Eq. 18)
uniform vec4 u_kneiphof2025_levels_b;      // L^(5..8)
uniform bool u_kneiphof2025_wang2020_style;
uniform float u_kneiphof2025_gamma_solid_angle;
uniform bool u_kneiphof2025_conditional;
uniform int u_kneiphof2025_smooth;  // KNEIPHOF2025_SMOOTH_*
uniform float u_kneiphof2025_microfacet_roughness;
uniform bool u_kneiphof2025_light_sized_grid;  // "area_grid": "light_size"
uniform float u_kneiphof2025_screen_space_scale;
uniform float u_kneiphof2025_density_randomization;
uniform vec3 u_kneiphof2025_f0;             // kneiphof2025_f0(desc)
uniform float u_kneiphof2025_radiance_scale; // current environment scale / prefiltered one
// alpha_of (kneiphof2025.cpp): per fragment under a roughness map, a normal
// map or curvature (glints/glint_uniforms.glsl).
float kneiphof2025_glue_alpha() { return kneiphof2025_isotropic_alpha(u_glint_alpha); }
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(deliot2023_ndf(h, fp, NDF_GGX, u_glint_alpha.x, u_glint_alpha.y,
                               g_glint_slope_correlation,
                               u_glint_log_density, u_glint_seed,
                               u_kneiphof2025_microfacet_roughness,
                               u_kneiphof2025_screen_space_scale,
                               u_kneiphof2025_density_randomization, false,
                               u_kneiphof2025_conditional));
}
#define GLINTLAB_GLINT_SHADES_ENVIRONMENT 1
// Eq. 17 under the environment (unshadowed, 003 §7); wo local, (t, b, n) the
// world shading frame; wr the mirror direction in world space.
vec3 glint_environment(vec3 wo, vec3 t, vec3 b, vec3 n, vec3 color, Footprint fp) {
    if (wo.z <= 0.0f) return vec3(0.0f);
    vec3 wr = (-wo.x) * t + (-wo.y) * b + wo.z * n;
    return u_kneiphof2025_radiance_scale *
           kneiphof2025_environment(n, wr, wo.z, kneiphof2025_glue_alpha(), u_kneiphof2025_f0,
                                    color, fp, u_glint_log_density, u_glint_seed,
                                    u_kneiphof2025_screen_space_scale,
                                    u_kneiphof2025_density_randomization, u_kneiphof2025_levels,
                                    u_kneiphof2025_levels_a, u_kneiphof2025_levels_b,
                                    u_kneiphof2025_wang2020_style ? KNEIPHOF2025_VARIANT_WANG2020
                                                                  : KNEIPHOF2025_VARIANT_OURS,
                                    u_kneiphof2025_gamma_solid_angle, u_kneiphof2025_conditional,
                                    u_kneiphof2025_smooth);
}
#define GLINTLAB_GLINT_SHADES_AREA_LIGHTS 1
// One area light (K = 1): a cone around the world direction `axis`; the
// caller multiplies by the shadow test towards the axis.
vec3 glint_area_light(vec3 axis, float cos_max, vec3 radiance, vec3 t, vec3 b, vec3 n, vec3 wo,
                      vec3 color, Footprint fp) {
    if (wo.z <= 0.0f) return vec3(0.0f);
    return kneiphof2025_area_light(axis, cos_max, radiance, t, b, n, wo, kneiphof2025_glue_alpha(),
                                   u_kneiphof2025_f0, color, fp, u_glint_log_density,
                                   u_glint_seed, u_kneiphof2025_microfacet_roughness,
                                   u_kneiphof2025_light_sized_grid,
                                   u_kneiphof2025_screen_space_scale,
                                   u_kneiphof2025_density_randomization, u_kneiphof2025_conditional);
}

#endif
