// C++ view of the shared counting laws (binomial_laws.glsl, multinomial.glsl,
// distributed_binomial.glsl), in namespace glintlab::shader.
//
// The .glsl functions are plain (non-inline) definitions, so they are compiled
// in exactly one translation unit, laws.cpp; this header declares them. A
// signature that drifts from its .glsl definition fails at link time.
#pragma once

#include "glintlab/core/glsl.h"

GLINTLAB_SHADER_BEGIN
#include "glintlab/core/constants.glsl"

// normal_quantile.glsl
float normal_quantile(float u);
// binomial_laws.glsl
float pow_one_minus_naive(float p, float N);
float pow_unit(float x, float y);
float stable_pow_scale(float p);
float pow_one_minus_stable(float p, float N);
float gaussian_deviate(float mean, float variance, float xi);
float binomial_gaussian(float N, float p, float xi);
float binomial_zirr2016(float N, float p, float xi_gauss, mat4 xi_trials);
float binomial_deliot2023(float N, float p, float xi0, float xi1);
float binomial_single_gated(float N, float p, float xi1, float xi2);
float standard_normal_cdf(float x);
float clamped_gaussian_mean(float mean, float sd, float lo, float hi);
float binomial_single_gated_conditional(float N, float p, float xi1, float xi2);
vec2 binomial_dual_gated(float N, float p, float xi1, float xi2, bool integer_gaussian);
vec2 binomial_dual_gated_conditional(float N, float p, float xi1, float xi2, bool integer_gaussian);
// multinomial.glsl
float multinomial_level(INOUT(float) remaining, float p_bin, float p_rest, float xi1, float xi2);
vec4 multinomial4(float N, vec4 probs, vec4 xi1, vec4 xi2);
void multinomial8(float N, vec4 probs_a, vec4 probs_b, vec4 xi1_a, vec4 xi2_a, vec4 xi1_b,
                  vec4 xi2_b, OUT(vec4) counts_a, OUT(vec4) counts_b);
// distributed_binomial.glsl
float stratified_trial_count(float N, float area);
float lod_top_weight(float P, float P_top, float P_bottom);
vec2 distributed_binomial_trials(float N, float P, float P_top, float P_bottom);
float output_blend(float count_top, float count_bottom, float w_top);
GLINTLAB_SHADER_END
