// kneiphof2025 (Kneiphof & Klein 2025, 003 §5): the fuzzy partition of a luminance into the
// K radiance levels, shared by the CPU prefilter (kneiphof2025_prefilter.cpp)
// and the GPU's per-frame prefilter (glints/kneiphof2025/kneiphof2025_prefilter_gpu.cpp).
#ifndef GLINTLAB_GLINTS_KNEIPHOF2025_PARTITION_GLSL
#define GLINTLAB_GLINTS_KNEIPHOF2025_PARTITION_GLSL

// Eq. 19 in linear space: the hat functions of the two levels around the
// luminance (levels L_a = L^(1..4), L_b = L^(5..8), ascending, L^(1) = 0);
// the weights w_a (k = 1..4), w_b (k = 5..8) sum to 1 and sum_k w L^(k) = L
// for L in [0, L^(K)]. Equal levels (a constant environment: all k > 1 equal)
// give the whole weight to the upper one.
void kneiphof2025_partition(float luminance, int levels, vec4 L_a, vec4 L_b, OUT(vec4) w_a,
                            OUT(vec4) w_b) {
    float L[8];
    float w[8];
    for (int k = 0; k < 4; ++k) {
        L[k] = L_a[k];
        L[k + 4] = L_b[k];
    }
    for (int k = 0; k < 8; ++k) w[k] = 0.0f;
    float l = clamp(luminance, 0.0f, L[levels - 1]);
    bool found = false;
    for (int j = 0; j + 1 < levels; ++j) {
        if (found) continue;
        float a = L[j];
        float b = L[j + 1];
        if (l <= b) {
            float t = b > a ? (l - a) / (b - a) : 1.0f;
            w[j] = 1.0f - t;
            w[j + 1] = t;
            found = true;
        }
    }
    if (!found) w[levels - 1] = 1.0f;
    w_a = vec4(w[0], w[1], w[2], w[3]);
    w_b = vec4(w[4], w[5], w[6], w[7]);
}

#endif
