// GPU glue of chermain2020 (Chermain et al. 2020, 004) for the forward pass
// (realtime/forward_shaders.h):
// defines, from the model's shared .glsl and the uniforms set by
// realtime/glint_programs.cpp (glint_model_glue_path selects this file),
//     vec3 glint_ndf(vec3 h, Footprint fp);  // D_P(h), RGB (glints/material.glsl)
// RGB D_P of Eq. 13 with the colour table, the dictionary through
// chermain2020.glsl's own sampler `chermain2020_dictionary` (its masking,
// Smith or 004 Eq. 14-16's V-cavity, is material.glsl's GLINT_G2_*).
#ifndef GLINTLAB_GLINTS_CHERMAIN2020_CHERMAIN2020_GPU_GLSL
#define GLINTLAB_GLINTS_CHERMAIN2020_CHERMAIN2020_GPU_GLSL

// The dictionary as pairs of neighbouring samples (chermain2020.glsl;
// uploaded so by chermain2020_gpu.cpp).
#define GLINTLAB_CHERMAIN2020_DICT_PAIRS 1
#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/glints/chermain2020/chermain2020.glsl"
uniform ivec3 u_chermain2020_dict_shape;  // n_levels, n_dists, table_size
uniform vec2 u_chermain2020_dict_range;   // alpha_dict, slope_max
uniform float u_chermain2020_relative_area;
uniform float u_chermain2020_max_anisotropy;
uniform float u_chermain2020_density_randomization;
uniform int u_chermain2020_colour_count;
// "slope_correlation": "chermain2021": the target is sheared by the slopes'
// correlation the forward pass or the export's inputs resolved per pixel.
uniform bool u_chermain2020_correlated;
uniform vec3 u_chermain2020_colours[CHERMAIN2020_MAX_COLOURS];
#ifdef GLINTLAB_GLINT_VIEW_DIFFERENTIALS
#include "glintlab/core/half_slope_differentials.glsl"
// "antialiasing": "chermain2021": the kernel (> 0, "antialiasing_kernel") of
// the geometric glint anti-aliasing over the pass's view differentials;
// 0 ("none"): unfiltered. The filter reads chermain2020_dictionary_filter.
uniform float u_chermain2020_ggaa_kernel;
#endif
vec3 glint_ndf(vec3 h, Footprint fp) {
    Chermain2020Dict d;
    d.n_levels = u_chermain2020_dict_shape.x;
    d.n_dists = u_chermain2020_dict_shape.y;
    d.table_size = u_chermain2020_dict_shape.z;
    d.alpha_dict = u_chermain2020_dict_range.x;
    d.slope_max = u_chermain2020_dict_range.y;
    Chermain2020Colours colours;
    colours.count = u_chermain2020_colour_count;
    for (int i = 0; i < CHERMAIN2020_MAX_COLOURS; ++i) colours.table[i] = u_chermain2020_colours[i];
    float rho = u_chermain2020_correlated ? g_glint_slope_correlation : 0.0f;
    Chermain2020Filter ggaa = chermain2020_unfiltered();
#ifdef GLINTLAB_GLINT_VIEW_DIFFERENTIALS
    if (u_chermain2020_ggaa_kernel > 0.0f) {
        vec4 sweep = half_slope_differentials(h, g_glint_view);
        ggaa.slope_dx = vec2(sweep.x, sweep.y);
        ggaa.slope_dy = vec2(sweep.z, sweep.w);
        ggaa.kernel = u_chermain2020_ggaa_kernel;
    }
#endif
    return chermain2020_ndf_rgb(h, fp, d, u_glint_alpha.x, u_glint_alpha.y, rho, u_glint_log_density,
                                u_glint_seed, u_chermain2020_relative_area,
                                u_chermain2020_max_anisotropy,
                                u_chermain2020_density_randomization, colours, ggaa);
}

#endif
