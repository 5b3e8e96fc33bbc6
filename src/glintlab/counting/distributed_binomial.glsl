// Counting between two LOD levels (000 §3-4). A footprint of area P lies
// between a bottom LOD cell of area P_bottom and a top LOD cell of area P_top
// (P_bottom <= P <= P_top); N is the trial (facet) density per unit area.
#ifndef GLINTLAB_COUNTING_DISTRIBUTED_BINOMIAL_GLSL
#define GLINTLAB_COUNTING_DISTRIBUTED_BINOMIAL_GLSL

// Eq. 9: with stratified trials (one jittered facet per texel) an area A
// holds floor(N A) trials. (Eq. 8, uniform trials, makes that count itself
// binomial b(N, A); it is sampled on the C++ side for comparison only.)
float stratified_trial_count(float N, float area) {
    return floor(N * area);
}

// Weight of the top level in Eq. 10: P = w_top P_top + (1 - w_top) P_bottom.
float lod_top_weight(float P, float P_top, float P_bottom) {
    return P_top > P_bottom ? clamp((P - P_bottom) / (P_top - P_bottom), 0.0f, 1.0f) : 1.0f;
}

// Eq. 10: trial counts of the two binomials whose sum is the distributed
// binomial b(N P, p) = b_top(w_top N P_top, p) + b_bottom(w_bottom N P_bottom, p);
// the two binomials use the seeds of their own LOD level. By additivity of
// the binomial law the sum has N P trials.
vec2 distributed_binomial_trials(float N, float P, float P_top, float P_bottom) {
    float w_top = lod_top_weight(P, P_top, P_bottom);
    return vec2(w_top * N * P_top, (1.0f - w_top) * N * P_bottom);
}

// Eq. 7, zirr2016's output blending: a mix of the counts of the two levels.
// Its mean is right, its variance is not (the two counts are independent),
// which is what 000 Fig. 4 shows.
float output_blend(float count_top, float count_bottom, float w_top) {
    return mix(count_bottom, count_top, w_top);
}

#endif
