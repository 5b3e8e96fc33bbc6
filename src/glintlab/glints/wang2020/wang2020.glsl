// wang2020 per-pixel combination (Wang et al. 2020, 001 §4.3), the part
// a GPU shader runs after fetching its tables: the three-scale selection and
// Eqs. 18-21. Shared by the CPU path (wang2020_shading.cpp) and GLSL.
// Inputs: lhat, phat = L̂o(n, o), P̂(n, o) (Eqs. 16-17, prefilter table);
// count = Σ_k 1_A(x_k) (quadtree); accepted = Σ_k 1_A(x_k) H (λ_k < P̂ or P);
// area = a(A); total = N; sigma = σ(Ωo) = 2π(1 − cos γ).
#ifndef GLINTLAB_GLINTS_WANG2020_GLSL
#define GLINTLAB_GLINTS_WANG2020_GLSL

const int WANG2020_MICRO = 0;
const int WANG2020_MESO = 1;
const int WANG2020_MACRO = 2;

// §4.3: < 4 expected particles micro, 4-64 meso, > 64 macro.
int wang2020_select_scale(float expected_count) {
    if (expected_count < 4.0f) return WANG2020_MICRO;
    if (expected_count <= 64.0f) return WANG2020_MESO;
    return WANG2020_MACRO;
}

// num / den for the counting estimates below: 0 where den is not a normal
// float (a footprint of area ~0, or a tiny phat, make it underflow; the count
// is then 0 as well and 0 / 0 was NaN). Bit for bit num / den otherwise.
float wang2020_count_quotient(float num, float den) {
    return den >= 1.17549435e-38f ? num / den : 0.0f;
}

// Environment radiance (before tint): Eq. 20 (micro), Eq. 18 (meso), Eq. 18
// with Σ 1_A ≈ N a(A) (macro).
vec3 wang2020_environment_combine(int scale, vec3 lhat, float phat, float count, float accepted,
                                  float area, float total, float sigma) {
    if (scale == WANG2020_MACRO) return lhat / sigma;
    if (scale == WANG2020_MESO) return lhat * wang2020_count_quotient(count, sigma * area * total);
    if (!(phat > 0.0f)) return vec3(0.0f);
    return lhat * wang2020_count_quotient(accepted, sigma * area * total * phat);
}

// D̂'(A, o, i) = D̂ / (a σ) of Eq. 21 with D̂ from Eq. 5 (meso), Eq. 7
// (micro: accepted particles with probability P) or P (macro).
float wang2020_point_dprime(int scale, float p, float count, float accepted, float area,
                            float total, float sigma) {
    if (scale == WANG2020_MACRO) return p / sigma;
    if (scale == WANG2020_MESO) return wang2020_count_quotient(count * p, total * area * sigma);
    return wang2020_count_quotient(accepted, total * area * sigma);
}

// ---- "micro": "per_particle" (docs/MODELS.md, wang2020) ----
// Blend weights (micro, meso, macro) of the per_particle mode: log2-linear
// bands over expected counts [2, 8] (micro -> meso) and [32, 128] (meso ->
// macro), centred on the paper's thresholds 4 and 64. Each scale's estimate
// has the same expectation (micro and meso even conditionally on the
// particles in A), so any convex blend keeps the mean; the blend removes the
// jump in texture (variance) at the thresholds.
vec3 wang2020_scale_weights(float expected_count) {
    if (!(expected_count > 2.0f)) return vec3(1.0f, 0.0f, 0.0f);
    if (expected_count < 8.0f) {
        float t = 0.5f * log2(expected_count * 0.5f);
        return vec3(1.0f - t, t, 0.0f);
    }
    if (expected_count <= 32.0f) return vec3(0.0f, 1.0f, 0.0f);
    if (expected_count < 128.0f) {
        float t = 0.5f * log2(expected_count * (1.0f / 32.0f));
        return vec3(0.0f, 1.0f - t, t);
    }
    return vec3(0.0f, 0.0f, 1.0f);
}

// The micro scale's enumeration bound under the "effective" scale count
// (wang2020_shading.h ScaleCount::Effective): its cost bound.
const float WANG2020_MICRO_ENUMERATION_MAX = 4096.0f;

// Blend weights (micro, meso, macro) of the "effective" scale count for a
// footprint of `count` expected particles whose micro estimate has relative
// variance 1 / e, e = count · fraction (wang2020_shading.h ScaleCount): the
// micro scale up to e = 64, blended log2-linearly into the macro scale over
// e in [64, 256]. The meso scale (count × table) is not used: its only
// texture is the count's 1/sqrt(count), not the 1/sqrt(e) of the particles'
// contributions, so in the meso band the pixels were as frozen as in the
// macro one (compare's flicker ratio 0.2-0.4 under the environments). Near
// the enumeration bound the micro scale fades out: over counts [bound / 2,
// bound] (log2-linear) towards the macro scale. `count` is the footprint
// parallelogram's, `visited` the box's whose particles the enumeration
// visits (equal without a parallelogram). Convex blends of estimates with
// the same mean: the mean is kept.
vec3 wang2020_effective_weights(float count, float visited, float fraction) {
    float effective = count * clamp(fraction, 0.0f, 1.0f);
    float micro = 1.0f - clamp(0.5f * log2(max(effective, 1e-30f) * (1.0f / 64.0f)), 0.0f, 1.0f);
    float t =
        clamp(log2(max(visited, 1.0f) * (2.0f / WANG2020_MICRO_ENUMERATION_MAX)), 0.0f, 1.0f);
    micro *= 1.0f - t;
    return vec3(micro, 0.0f, 1.0f - micro);
}

// Environment radiance (before tint), per_particle mode: micro = (1/(a N))
// Σ_{k in A} L_γ(i_k) M(i_k, o) (particle_sum holds the Σ), blended with
// Eq. 18 (meso) and its macro limit by the weights w.
vec3 wang2020_environment_blend(vec3 w, vec3 lhat, vec3 particle_sum, float count, float area,
                                float total, float sigma) {
    vec3 r = vec3(0.0f);
    if (w.x > 0.0f) r += w.x * particle_sum / (area * total);
    if (w.y > 0.0f) r += w.y * lhat * (count / (sigma * area * total));
    if (w.z > 0.0f) r += w.z * lhat / sigma;
    return r;
}

// D̂'(A, o, i) of Eq. 21, per_particle mode: lit = number of particles in A
// whose own normal reflects i into the γ cone around o (probability P each).
float wang2020_point_dprime_blend(vec3 w, float p, float count, float lit, float area, float total,
                                  float sigma) {
    float r = 0.0f;
    if (w.x > 0.0f) r += w.x * lit / (total * area * sigma);
    if (w.y > 0.0f) r += w.y * count * p / (total * area * sigma);
    if (w.z > 0.0f) r += w.z * p / sigma;
    return r;
}

#endif  // GLINTLAB_GLINTS_WANG2020_GLSL
