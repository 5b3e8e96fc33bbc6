// Multinomial sampling of N trials over K bins by hierarchical dual-gated
// binomials (003 §6): bin k takes b(remaining, p_k / (p_k + ... + p_K-1)) of
// the trials not yet assigned, the last bin takes the rest. Constant cost in
// N; K is fixed (4 or 8 as in 003). Counts are >= 0 and, for integer N, sum
// to N exactly (the Gaussian part is rounded so every count is an integer).
#ifndef GLINTLAB_COUNTING_MULTINOMIAL_GLSL
#define GLINTLAB_COUNTING_MULTINOMIAL_GLSL

#include "glintlab/counting/binomial_laws.glsl"

// One level of the hierarchy: the count of a bin of probability p_bin among
// `remaining` trials whose bins have total probability p_rest (>= p_bin).
// `remaining` becomes the trials left for the next bins.
float multinomial_level(INOUT(float) remaining, float p_bin, float p_rest, float xi1, float xi2) {
    float q = p_rest > 0.0f ? clamp(p_bin / p_rest, 0.0f, 1.0f) : 0.0f;
    vec2 counts = binomial_dual_gated(remaining, q, xi1, xi2, true);
    remaining = counts.y;
    return counts.x;
}

// K = 4 bins with probabilities `probs` (normalised here by their sum).
// xi1, xi2: the two uniforms of each of the 3 levels (w unused).
vec4 multinomial4(float N, vec4 probs, vec4 xi1, vec4 xi2) {
    float remaining = max(N, 0.0f);
    vec4 counts = vec4(0.0f);
    float rest_w = probs.w;
    float rest_z = probs.z + rest_w;
    float rest_y = probs.y + rest_z;
    float rest_x = probs.x + rest_y;
    counts.x = multinomial_level(remaining, probs.x, rest_x, xi1.x, xi2.x);
    counts.y = multinomial_level(remaining, probs.y, rest_y, xi1.y, xi2.y);
    counts.z = multinomial_level(remaining, probs.z, rest_z, xi1.z, xi2.z);
    counts.w = remaining;
    return counts;
}

// K = 8 bins: probs_a holds bins 0-3, probs_b bins 4-7; 7 levels use the
// uniforms xi1_a/xi2_a (levels 0-3) and xi1_b/xi2_b (levels 4-6, w unused).
void multinomial8(float N, vec4 probs_a, vec4 probs_b, vec4 xi1_a, vec4 xi2_a, vec4 xi1_b,
                  vec4 xi2_b, OUT(vec4) counts_a, OUT(vec4) counts_b) {
    float remaining = max(N, 0.0f);
    float tail_b = probs_b.x + probs_b.y + probs_b.z + probs_b.w;
    float rest_a3 = probs_a.w + tail_b;
    float rest_a2 = probs_a.z + rest_a3;
    float rest_a1 = probs_a.y + rest_a2;
    float rest_a0 = probs_a.x + rest_a1;
    counts_a.x = multinomial_level(remaining, probs_a.x, rest_a0, xi1_a.x, xi2_a.x);
    counts_a.y = multinomial_level(remaining, probs_a.y, rest_a1, xi1_a.y, xi2_a.y);
    counts_a.z = multinomial_level(remaining, probs_a.z, rest_a2, xi1_a.z, xi2_a.z);
    counts_a.w = multinomial_level(remaining, probs_a.w, rest_a3, xi1_a.w, xi2_a.w);
    counts_b = multinomial4(remaining, probs_b, xi1_b, xi2_b);
}

#endif
