// GPU glue of deliot2023 (Deliot & Belcour 2023, 000) for the forward pass
// (realtime/forward_shaders.h):
// defines, from the model's shared .glsl and the uniforms set by
// realtime/glint_programs.cpp (glint_model_glue_path selects this file),
//     vec3 glint_ndf(vec3 h, Footprint fp);  // D_P(h), RGB (glints/material.glsl)
// D_P of Eq. 3-4 with the hash uniforms (the CPU default; the 64x64
// noise-table variant is deliot2023_noise_texture_gpu.glsl).
#ifndef GLINTLAB_GLINTS_DELIOT2023_DELIOT2023_GPU_GLSL
#define GLINTLAB_GLINTS_DELIOT2023_DELIOT2023_GPU_GLSL

// D_P's expectation where the counts cannot differ from it in fp32
// (deliot2023.glsl deliot2023_expectation_exit; the CPU evaluates in full).
#define GLINTLAB_DELIOT2023_EXPECTATION_EXITS 1
// The half-vector-free part of D_P once per footprint, not once per light
// (deliot2023.glsl deliot2023_cached_pixel_part).
#define GLINTLAB_DELIOT2023_PIXEL_CACHE 1
#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/glints/deliot2023/deliot2023.glsl"
uniform float u_deliot2023_microfacet_roughness;
uniform float u_deliot2023_screen_space_scale;
uniform float u_deliot2023_density_randomization;
uniform bool u_deliot2023_original_defects;
uniform bool u_deliot2023_conditional;  // "gaussian": "conditional" (binomial_laws.glsl Law 5b)
#ifdef GLINTLAB_DELIOT2023_STOCHASTIC_GRID
// Option stochastic_grid: one grid per pixel, drawn from the pixel, the
// material's seed and the frame number (deliot2023_ndf_stochastic).
uniform uint u_deliot2023_frame;
vec3 glint_ndf(vec3 h, Footprint fp) {
    if (u_deliot2023_original_defects)
        return vec3(deliot2023_ndf(h, fp, u_glint_ndf, u_glint_alpha.x, u_glint_alpha.y,
                                   g_glint_slope_correlation, u_glint_log_density, u_glint_seed,
                                   u_deliot2023_microfacet_roughness,
                                   u_deliot2023_screen_space_scale,
                                   u_deliot2023_density_randomization, true,
                                   u_deliot2023_conditional));
    uint pixel = hash_cell(ivec2(gl_FragCoord.xy), u_glint_seed ^ 0x5bd1e995u);
    float u = uint_to_unit_float(pcg_hash(pixel ^ (u_deliot2023_frame * 0x9e3779b9u)));
    return vec3(deliot2023_ndf_stochastic(h, fp, u_glint_ndf, u_glint_alpha.x, u_glint_alpha.y,
                                          g_glint_slope_correlation, u_glint_log_density,
                                          u_glint_seed,
                                          u_deliot2023_microfacet_roughness,
                                          u_deliot2023_screen_space_scale,
                                          u_deliot2023_density_randomization,
                                          u_deliot2023_conditional, u));
}
#else
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(deliot2023_ndf(h, fp, u_glint_ndf, u_glint_alpha.x, u_glint_alpha.y,
                               g_glint_slope_correlation, u_glint_log_density, u_glint_seed,
                               u_deliot2023_microfacet_roughness, u_deliot2023_screen_space_scale,
                               u_deliot2023_density_randomization, u_deliot2023_original_defects,
                               u_deliot2023_conditional));
}
#endif

#endif
