// kneiphof2025: Kneiphof & Klein, "Real-Time Image-based Lighting of Glints",
// EGSR/CGF 2025 (003), with its area-light special case K = 1
// (kneiphof2024, restated in 003 Eq. 4-9). Equation numbers are 003's.
//
// The glint model only modulates the radiance of the equivalent smooth
// surface (003 §1 "core assumptions"):
//   L_P(wo) = L_o(wo) * sum_k L^(k) M_k(N_P, p) / (E[N_P] sum_k L^(k) p^(k))   (Eq. 17)
// with L_o the split-sum smooth radiance (Eq. 11), L^(k) the K radiance levels
// of the environment (Eq. 18), p^(k) the probability that a facet reflects
// level k (Eq. 15, 20-21: E_D(wo)/D_H times the prefiltered fuzzy indicator
// w^(k), Eq. 19), and M the multinomial counts of the N_P facets of the
// footprint (§6: hierarchical dual-gated binomials, Algorithm 1) distributed
// over deliot2023's anisotropic grid without the half-vector dimension (Eq. 10).
//
// Prefiltered inputs come through fetch functions the back end defines:
//   vec3 kneiphof2025_radiance_fetch(vec3 dir, float roughness)
//        prefiltered radiance (second integral of Eq. 11) at a world direction,
//        roughness = sqrt(alpha) in [0, 1];
//   vec4 kneiphof2025_weights_fetch(vec3 dir, float roughness, int group)
//        prefiltered fuzzy indicators w^(4 group + 1 .. 4 group + 4) (the
//        integral of Eq. 21), group 0 or 1;
//   vec3 kneiphof2025_dfg_fetch(float cos_o, float roughness)
//        (A, B, E_D / D_H): split-sum albedo E_rho = F0 A + B (Eq. 11) and the
//        visible reflecting facet area over the total facet area (Eq. 21, 8);
//   vec4 kneiphof2025_radiance_sources_fetch(vec3 dir, float roughness)
//        the prefiltered radiance (rgb) and the luminance of the environment's
//        bright sources in it (w: their radiance above their surroundings
//        alone, prefiltered by the same kernel);
//   int kneiphof2025_source_count()
//        0 (no source) to KNEIPHOF2025_SOURCES directions inside the sources
//        taken out of the prefiltered radiance (Kneiphof2025Sources,
//        kneiphof2025_prefilter.h);
//   void kneiphof2025_source(int k, OUT(vec3) direction, OUT(vec3) power,
//                            OUT(float) radius)
//        direction k: world direction, RGB power (radiance above the
//        surroundings x solid angle), the angular radius it stands for;
//   vec3 kneiphof2025_sources_color()
//        sum of the powers / its luminance (the colour of the w channel);
//   vec2 kneiphof2025_cone_jitter()
//        the position of the next sample of an area light's quadrature within
//        its stratum, in [0, 1)^2 (the CPU draws it from the pixel's stream,
//        the GPU takes the stratum's centre).
// The C++ back end (kneiphof2025.cpp) defines them over its CPU prefiltered
// maps before including this file; the GLSL defaults below read lat-long
// texture arrays whose layer i holds roughness i / (layers - 1).
#ifndef GLINTLAB_GLINTS_KNEIPHOF2025_GLSL
#define GLINTLAB_GLINTS_KNEIPHOF2025_GLSL

#include "glintlab/core/constants.glsl"
#include "glintlab/core/footprint.glsl"
#include "glintlab/core/frame.glsl"
#include "glintlab/core/hash.glsl"
#include "glintlab/counting/binomial_laws.glsl"
#include "glintlab/glints/deliot2023/deliot2023.glsl"
#include "glintlab/microfacet/fresnel.glsl"
#include "glintlab/microfacet/masking.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/microfacet/vndf.glsl"

// Directions the bright sources are shaded by (Kneiphof2025Sources::kSamples).
const int KNEIPHOF2025_SOURCES = 16;

#ifndef GLINTLAB_CPP
// Texture arrays, one layer per roughness level (layer i: sqrt(alpha) =
// i / (layers - 1)), lat-long in the EnvironmentMap convention (v = 0 at the
// zenith): RGB radiance, the weights of levels 1-4 and of levels 5-8.
uniform sampler2DArray kneiphof2025_radiance_layers;
uniform sampler2DArray kneiphof2025_weights_layers_a;
uniform sampler2DArray kneiphof2025_weights_layers_b;
// RGB = (A, B, E_D / D_H) at (cos_o, roughness) texel centres.
uniform sampler2D kneiphof2025_dfg_lut;
uniform float kneiphof2025_env_rotation;  // radians about +y
uniform float kneiphof2025_last_layer;    // layers - 1
// The bright sources (Kneiphof2025Sources): per direction world direction,
// RGB power, angular radius; the colour of the radiance array's alpha.
uniform int u_kneiphof2025_source_count;
uniform vec3 u_kneiphof2025_source_direction[KNEIPHOF2025_SOURCES];
uniform vec3 u_kneiphof2025_source_power[KNEIPHOF2025_SOURCES];
uniform float u_kneiphof2025_source_radius[KNEIPHOF2025_SOURCES];
uniform vec3 u_kneiphof2025_sources_color;

vec2 kneiphof2025_latlong_uv(vec3 d) {
    float theta = acos(clamp(d.y, -1.0f, 1.0f));
    float phi = atan(d.x, -d.z) - kneiphof2025_env_rotation;
    float u = 0.5f + phi / TWO_PI;
    return vec2(u - floor(u), theta / PI);
}
// Bilinear within a layer, linear between the two layers around roughness.
vec4 kneiphof2025_layers_fetch(sampler2DArray layers, vec3 dir, float roughness) {
    vec2 uv = kneiphof2025_latlong_uv(dir);
    float l = clamp(roughness, 0.0f, 1.0f) * kneiphof2025_last_layer;
    float l0 = min(floor(l), kneiphof2025_last_layer);
    float l1 = min(l0 + 1.0f, kneiphof2025_last_layer);
    vec4 a = textureLod(layers, vec3(uv.x, uv.y, l0), 0.0f);
    vec4 b = textureLod(layers, vec3(uv.x, uv.y, l1), 0.0f);
    return mix(a, b, l - l0);
}
vec3 kneiphof2025_radiance_fetch(vec3 dir, float roughness) {
    vec4 t = kneiphof2025_layers_fetch(kneiphof2025_radiance_layers, dir, roughness);
    return vec3(t.x, t.y, t.z);
}
// The radiance array's alpha holds the sources channel.
vec4 kneiphof2025_radiance_sources_fetch(vec3 dir, float roughness) {
    return kneiphof2025_layers_fetch(kneiphof2025_radiance_layers, dir, roughness);
}
int kneiphof2025_source_count() {
    return clamp(u_kneiphof2025_source_count, 0, KNEIPHOF2025_SOURCES);
}
void kneiphof2025_source(int k, OUT(vec3) direction, OUT(vec3) power, OUT(float) radius) {
    direction = u_kneiphof2025_source_direction[k];
    power = u_kneiphof2025_source_power[k];
    radius = u_kneiphof2025_source_radius[k];
}
vec3 kneiphof2025_sources_color() {
    return u_kneiphof2025_sources_color;
}
vec4 kneiphof2025_weights_fetch(vec3 dir, float roughness, int group) {
    return group == 0 ? kneiphof2025_layers_fetch(kneiphof2025_weights_layers_a, dir, roughness)
                      : kneiphof2025_layers_fetch(kneiphof2025_weights_layers_b, dir, roughness);
}
vec3 kneiphof2025_dfg_fetch(float cos_o, float roughness) {
    vec4 t = textureLod(kneiphof2025_dfg_lut, vec2(cos_o, roughness), 0.0f);
    return vec3(t.x, t.y, t.z);
}
// A forward shader has no per-pixel stream: the midpoint of each stratum
// (deterministic; differs from the CPU's jittered strata by the quadrature
// error of 64 strata).
vec2 kneiphof2025_cone_jitter() {
    return vec2(0.5f, 0.5f);
}
#endif

const int KNEIPHOF2025_VARIANT_OURS = 0;
const int KNEIPHOF2025_VARIANT_WANG2020 = 1;

// D_H = integral of D over all facet orientations (003 §3.2) for isotropic
// GGX, in closed form: with t = tan^2(theta), D_H = alpha^2 int_0^inf
// sqrt(1 + t) / (alpha^2 + t)^2 dt = 1 + alpha^2 atanh(b) / b, b = sqrt(1 - alpha^2)
// (atan(b') / b' with b' = sqrt(alpha^2 - 1) for alpha > 1); 2 at alpha = 1.
// (The authors' code approximates it by 1 + alpha^1.41.)
float kneiphof2025_total_facet_area(float alpha) {
    float a2 = alpha * alpha;
    float d = 1.0f - a2;
    float f;
    if (abs(d) < 1e-4f) {
        f = 1.0f + d / 3.0f;  // atanh(b)/b = 1 + b^2/3 + O(b^4), same for atan with b^2 < 0
    } else if (d > 0.0f) {
        float b = sqrt(d);
        f = 0.5f * log((1.0f + b) / (1.0f - b)) / b;
    } else {
        float b = sqrt(-d);
        f = atan(b) / b;
    }
    return 1.0f + a2 * f;
}

// The isotropic GGX alpha that the prefiltered maps, the split-sum tables
// and the area lights' quadrature read for a per-hit (alpha_x, alpha_y): a
// roughness map's, or a lobe widened by a normal map's or a curved surface's
// slope covariance (docs/MODELS.md, "Normal maps"). It keeps the lobe's total
// slope variance, alpha^2 = (alpha_x^2 + alpha_y^2) / 2, the trace of the
// slope matrix, which the slopes' correlation does not change; the tables
// cannot hold the anisotropy or the correlation, which drop out.
float kneiphof2025_isotropic_alpha(vec2 alpha) {
    return clamp(sqrt(0.5f * (alpha.x * alpha.x + alpha.y * alpha.y)), 1e-4f, 1.0f);
}

// Reflection probabilities (Eq. 15 with Eq. 21): p^(k) = (E_D / D_H) w^(k),
// where w^(k) are the prefiltered fuzzy indicators renormalised by their sum
// (prefiltering preserves the partition of unity only up to rounding; the
// authors' code renormalises at lookup too). Level 1 (L^(1) = 0) also
// takes the facets that reflect nothing visible, 1 - E_D / D_H (003 §5
// "Discrete Radiance Levels"), so the K probabilities sum to 1.
void kneiphof2025_probabilities(vec4 w_a, vec4 w_b, int levels, float p_visible, OUT(vec4) p_a,
                                OUT(vec4) p_b) {
    w_a = max(w_a, vec4(0.0f));
    w_b = levels > 4 ? max(w_b, vec4(0.0f)) : vec4(0.0f);
    float sum = w_a.x + w_a.y + w_a.z + w_a.w + w_b.x + w_b.y + w_b.z + w_b.w;
    float pv = clamp(p_visible, 0.0f, 1.0f);
    if (!(sum > 0.0f)) {
        p_a = vec4(1.0f, 0.0f, 0.0f, 0.0f);
        p_b = vec4(0.0f);
        return;
    }
    p_a = w_a * (pv / sum);
    p_b = w_b * (pv / sum);
    p_a.x += 1.0f - pv;
}

// Eq. 17's numerator for one vertex: the multinomial counts M_k of N trials
// over the K levels (003 §6: bin k takes a dual-gated binomial of the trials
// not yet assigned with probability p_k / (p_k + ... + p_K), the last bin the
// rest; the Gaussian part is rounded so integer N gives counts summing to N),
// weighted by the level radiances. The uniforms (2 per level) come from the
// vertex's stream. `conditional` selects binomial_dual_gated_conditional
// (counting/binomial_laws.glsl) instead of Algorithm 1 as published, and two
// fixes of ours that make the multinomial's mean exact (docs/MODELS.md):
//  - N is rounded stochastically to an integer first (floor(N + u), one more
//    uniform before the levels'; E = N): with a real N the Gaussian's
//    fractional part n2 - g flows down the chain into the last, brightest
//    level, +20-50 % on its count where it is rare (a sun);
//  - where p_k / (p_k + ... + p_K) > 1/2 the binomial is drawn for the
//    complement, with its probability (p_(k+1) + ... + p_K) / (p_k + ... + p_K)
//    from the suffix sums: 1 - q loses all precision in fp32 when the rest is
//    a rare bright level.
// `scale` (an exact power of two, see kneiphof2025_count_exponent) multiplies
// every count before its radiance does: L^(k) M_k overflows fp32 where
// N reaches e^80 (log density ~60, or density_randomization ~20) under a
// bright environment.
// Component k in [0, 8) of the levels' pair of vectors (a: 0-3, b: 4-7).
// The multinomial reads its levels through this instead of local float[8]
// arrays: a level loop bounded by the uniform K is not unrolled, and a local
// array indexed by a non-constant k is kept in scratch memory by Mesa's
// compiler (a gather per read), where a vector indexed so becomes selects
// (zirr2016_cell_law drops its 4 x 4 matrix for the same reason). Same values.
float kneiphof2025_level(vec4 a, vec4 b, int k) {
    return k < 4 ? a[k & 3] : b[k & 3];
}
float kneiphof2025_weighted_multinomial_scaled(float N, float scale, int levels, vec4 p_a, vec4 p_b,
                                               vec4 L_a, vec4 L_b, bool conditional,
                                               INOUT(uint) vs) {
    // Suffix sums p_k + ... + p_K, from the end (no cancellation).
    vec4 rest_a = vec4(0.0f);
    vec4 rest_b = vec4(0.0f);
    float acc = 0.0f;
    for (int k = 7; k >= 4; --k) {
        acc += k < levels ? p_b[k - 4] : 0.0f;
        rest_b[k - 4] = acc;
    }
    for (int k = 3; k >= 0; --k) {
        acc += k < levels ? p_a[k] : 0.0f;
        rest_a[k] = acc;
    }
    float remaining = max(N, 0.0f);
    if (conditional) remaining = floor(remaining + hash_random(vs));
    float value = 0.0f;
    // do-while loops here and below: a for loop costs SIMD back ends one
    // masked pass more (docs/ARCHITECTURE.md, "Writing shared code that SIMD
    // back ends run fast").
    if (levels > 1) {
        int k = 0;
        do {
            float rest_k = kneiphof2025_level(rest_a, rest_b, k);
            float q =
                rest_k > 0.0f ? clamp(kneiphof2025_level(p_a, p_b, k) / rest_k, 0.0f, 1.0f) : 0.0f;
            float xi1 = hash_random(vs);
            float xi2 = hash_random(vs);
            // One law evaluation whichever case (a SIMD back end runs every
            // side of a branch for a block of pixels): the complement's
            // probability where the conditional law draws the complement.
            bool complement = conditional && q > 0.5f;
            float q_rest = rest_k > 0.0f ? clamp(kneiphof2025_level(rest_a, rest_b, k + 1) / rest_k,
                                                 0.0f, 1.0f)
                                         : 0.0f;
            vec2 c = binomial_dual_gated_law(remaining, complement ? q_rest : q, xi1, xi2, true,
                                             conditional);
            if (complement) c = vec2(c.y, c.x);
            value += kneiphof2025_level(L_a, L_b, k) * (c.x * scale);
            remaining = c.y;
            ++k;
        } while (k < levels - 1);
    }
    return value + kneiphof2025_level(L_a, L_b, levels - 1) * (remaining * scale);
}
float kneiphof2025_weighted_multinomial(float N, int levels, vec4 p_a, vec4 p_b, vec4 L_a, vec4 L_b,
                                        bool conditional, INOUT(uint) vs) {
    return kneiphof2025_weighted_multinomial_scaled(N, 1.0f, levels, p_a, p_b, L_a, L_b,
                                                    conditional, vs);
}

// Sums of (radiance-weighted counts, trials) kept as (x, y) 2^e, e = z: a
// vertex with N > 2^64 contributes its counts scaled by 2^-e (e =
// kneiphof2025_count_exponent(N)), and the running sums are rescaled to the
// larger exponent. Scaling by powers of two is exact, so wherever every N
// is below 2^64 (e = 0) the sums are bit for bit the plain ones; above, the
// ratio x / y, which is all Eq. 17 uses, stays finite (it is at most the
// largest radiance level) where the plain sums overflowed to inf / inf = NaN.
float kneiphof2025_count_exponent(float N) {
    return N > 18446744073709551616.0f ? floor(log2(N)) - 63.0f : 0.0f;
}
// counts / (trials expected) for trials > 0: the plain quotient where the
// product is a normal float; otherwise (it underflows to 0 at log density
// -20 with a probability ~1e-38, or overflows) the quotients one by one, and
// 0 for no counts (0 / 0 was NaN).
float kneiphof2025_count_ratio(float counts, float trials, float expected) {
    float d = trials * expected;
    if (d >= 1.17549435e-38f && d <= 3.40282347e38f) return counts / d;
    return counts > 0.0f ? (counts / trials) / expected : 0.0f;
}
vec3 kneiphof2025_scaled_add(vec3 acc, vec2 v, float e) {
    if (e == acc.z) return vec3(acc.x + v.x, acc.y + v.y, e);
    if (e > acc.z) {
        int d = int(acc.z - e);
        return vec3(ldexp(acc.x, d) + v.x, ldexp(acc.y, d) + v.y, e);
    }
    int d = int(e - acc.z);
    return vec3(acc.x + ldexp(v.x, d), acc.y + ldexp(v.y, d), acc.z);
}

// One grid of the footprint (Eq. 10 without the half-vector dimension): per
// simplex vertex, the weighted multinomial counts of its N trials. Returns
// (sum_v beta_v sum_k L^(k) M_k, sum_v beta_v N_v) as scaled sums (x, y, e),
// see kneiphof2025_scaled_add. The vertex's stream gives the density jitter
// first (as in deliot2023), then the multinomial's uniforms.
vec3 kneiphof2025_grid_multinomial(ivec3 id, float weight, vec2 uv, float log_density, uint seed,
                                   float density_randomization, int levels, vec4 p_a, vec4 p_b,
                                   vec4 L_a, vec4 L_b, bool conditional) {
    Deliot2023Simplex s = deliot2023_simplex(id, weight, uv, log_density, seed);
    vec3 acc = vec3(0.0f);
    int v = 0;
    do {
        float bv = s.beta[v];
        if (!(bv <= 0.0f)) {
            uint vs = s.vertex_seed[v];
            float N = deliot2023_vertex_trials(s.log_trials, density_randomization, vs);
            float e = kneiphof2025_count_exponent(N);
            float scale = ldexp(1.0f, -int(e));
            float value = kneiphof2025_weighted_multinomial_scaled(N, scale, levels, p_a, p_b, L_a,
                                                                   L_b, conditional, vs);
            acc = kneiphof2025_scaled_add(acc, bv * vec2(value, N * scale), e);
        }
        ++v;
    } while (v < 3);
    return acc;
}

// The glint factor of Eq. 17 for a footprint: weighted multinomial sample over
// its expected value; mean 1 over realisations (Eq. 33). 1 where nothing
// reflects (then the smooth radiance is 0 as well).
float kneiphof2025_ibl_factor(Footprint fp, float log_density, uint seed, float screen_space_scale,
                              float density_randomization, int levels, vec4 p_a, vec4 p_b, vec4 L_a,
                              vec4 L_b, bool conditional) {
    float expected = dot(p_a, L_a) + (levels > 4 ? dot(p_b, L_b) : 0.0f);
    if (!(expected > 0.0f)) return 1.0f;
    Deliot2023Grids grids = deliot2023_footprint_grids(fp, screen_space_scale, false);
    vec3 acc = vec3(0.0f);
    int i = 0;
    do {
        if (!(grids.weight[i] <= 0.0f)) {
            vec3 g = kneiphof2025_grid_multinomial(deliot2023_grid_id(grids, i), grids.weight[i],
                                                   fp.uv, log_density, seed, density_randomization,
                                                   levels, p_a, p_b, L_a, L_b, conditional);
            acc = kneiphof2025_scaled_add(acc, vec2(g.x, g.y), g.z);
        }
        ++i;
    } while (i < 4);
    return acc.y > 0.0f ? kneiphof2025_count_ratio(acc.x, acc.y, expected) : 1.0f;
}

// K = 1 on the grid without the half-vector dimension: b(N_P, p) / (E[N_P] p)
// (the "wang2020-style" variant of 003 Fig. 8, whose p does not depend on the
// environment). 003 does not say which gated law its reimplementation uses;
// we take the dual-gated law (Algorithm 1), the same law as our multinomial
// with K = 2: the single-gated Eq. 23 (one success plus a Gaussian for the
// N - 1 others) overestimates E[b] by ~10-20 % where N p ~ 1-5 per vertex
// (measured: Kneiphof2025.GateFixesRemoveFig13And14Bias, docs/VALIDATION.md).
float kneiphof2025_binomial_factor_no_h(Footprint fp, float p, float log_density, uint seed,
                                        float screen_space_scale, float density_randomization,
                                        bool conditional) {
    if (!(p > 0.0f)) return 1.0f;
    Deliot2023Grids grids = deliot2023_footprint_grids(fp, screen_space_scale, false);
    vec2 acc = vec2(0.0f);
    int i = 0;
    do {
        if (grids.weight[i] <= 0.0f) {
            ++i;
            continue;
        }
        Deliot2023Simplex s = deliot2023_simplex(deliot2023_grid_id(grids, i), grids.weight[i],
                                                 fp.uv, log_density, seed);
        for (int v = 0; v < 3; ++v) {
            float bv = s.beta[v];
            if (bv <= 0.0f) continue;
            uint vs = s.vertex_seed[v];
            float N = deliot2023_vertex_trials(s.log_trials, density_randomization, vs);
            // As in the multinomial: an integer count (mean N) for the
            // conditional law, whose interior case is then exact.
            float n_trials = conditional ? floor(N + hash_random(vs)) : N;
            float xi1 = hash_random(vs);
            float xi2 = hash_random(vs);
            vec2 c = binomial_dual_gated_law(n_trials, p, xi1, xi2, conditional, conditional);
            acc += bv * vec2(c.x, N);
        }
        ++i;
    } while (i < 4);
    return acc.y > 0.0f ? kneiphof2025_count_ratio(acc.x, acc.y, p) : 1.0f;
}

// K = 1 area light (kneiphof2024; 003 Eq. 6-9, 23): b(N_P, p_Omega) on the
// full deliot2023 grid, whose angular dimension is indexed by the half vector
// h_c towards the light's centre in units of R (000 Eq. 14), with the
// single-gated law (Eq. 23), or its unbiased conditional form where
// `conditional` (kneiphof2025's "gaussian": "conditional", binomial_laws.glsl
// Law 5b). Returns b / (E[N_P] p), mean 1 (conditional).
float kneiphof2025_area_factor(vec3 h_center, Footprint fp, float p, float log_density, uint seed,
                               float microfacet_roughness, float screen_space_scale,
                               float density_randomization, bool conditional) {
    if (!(p > 0.0f)) return 1.0f;
    Deliot2023Grids grids = deliot2023_footprint_grids(fp, screen_space_scale, false);
    vec2 slope = vec2(h_center.x, h_center.y) / microfacet_roughness;
    vec2 acc = vec2(0.0f);
    int i = 0;
    do {
        if (!(grids.weight[i] <= 0.0f))
            acc += deliot2023_grid_counts(deliot2023_grid_id(grids, i), grids.weight[i], fp.uv,
                                          slope, p, log_density, seed, density_randomization, false,
                                          conditional);
        ++i;
    } while (i < 4);
    return acc.y > 0.0f ? kneiphof2025_count_ratio(acc.x, acc.y, p) : 1.0f;
}

// One area light (a sphere light, or the sun: a cone of constant radiance
// around the world direction `axis` with half-angle cosine cos_max) seen from
// a shading point with world frame (t, b, n) and local wo (wo.z > 0):
// Eq. 8-9 and the smooth reflected radiance by a stratified quadrature,
// uniform in solid angle, of KNEIPHOF2025_CONE_RINGS x _SECTORS strata
// (sample positions from kneiphof2025_cone_jitter(), two draws per stratum,
// ring-major):
//   p = int_cone D / (4 <h, wi>) dwi / D_H,   L = color int_cone F G2 D / (4 cos_o) L_i dwi.
// F is Schlick's with f0 (the split-sum convention, as for the environment).
// Returns L and sets p and the local half vector towards the cone's axis.
const int KNEIPHOF2025_CONE_RINGS = 8;
const int KNEIPHOF2025_CONE_SECTORS = 8;
vec3 kneiphof2025_integrate_cone(vec3 axis, float cos_max, vec3 radiance, vec3 t, vec3 b, vec3 n,
                                 vec3 wo, float alpha, vec3 f0, vec3 color, OUT(float) p,
                                 OUT(vec3) h_center) {
    vec3 c = axis;
    vec3 ct;
    vec3 cb;
    tangent_frame(c, ct, cb);
    float omega = 2.0f * PI * (1.0f - cos_max);
    float d_omega = omega / float(KNEIPHOF2025_CONE_RINGS * KNEIPHOF2025_CONE_SECTORS);
    float p_sum = 0.0f;
    vec3 L = vec3(0.0f);
    for (int i = 0; i < KNEIPHOF2025_CONE_RINGS; ++i) {
        for (int j = 0; j < KNEIPHOF2025_CONE_SECTORS; ++j) {
            vec2 jitter = kneiphof2025_cone_jitter();
            float u1 = (float(i) + jitter.x) / float(KNEIPHOF2025_CONE_RINGS);
            float u2 = (float(j) + jitter.y) / float(KNEIPHOF2025_CONE_SECTORS);
            float cos_t = 1.0f - u1 * (1.0f - cos_max);
            float sin_t = sqrt(max(1.0f - cos_t * cos_t, 0.0f));
            float phi = 2.0f * PI * u2;
            vec3 w = ct * (sin_t * cos(phi)) + cb * (sin_t * sin(phi)) + c * cos_t;
            vec3 wi = vec3(dot(w, t), dot(w, b), dot(w, n));
            if (wi.z <= 0.0f) continue;
            vec3 h = normalize(wo + wi);
            float d = D_Microfacet(NDF_GGX, h, alpha, alpha);
            float hi = max(dot(h, wi), 1e-6f);
            p_sum += d / (4.0f * hi) * d_omega;
            float g = G2_SmithCorrelated(NDF_GGX, wo, wi, alpha, alpha);
            vec3 f = F_Schlick(f0, hi);
            L += f * (g * d / (4.0f * wo.z) * d_omega) * radiance;
        }
    }
    p = clamp(p_sum / kneiphof2025_total_facet_area(alpha), 0.0f, 1.0f);
    h_center = normalize(wo + vec3(dot(axis, t), dot(axis, b), dot(axis, n)));
    return color * L;
}

// The angular cell size of an area light's glints (kneiphof2025's
// "area_grid"). As published it is deliot2023's R, the microfacets' own lobe
// (003 §8: the lifetime of glints under area lights "can be controlled
// manually by adjusting the grid resolution with respect to the halfway
// vector"). "light_size" (default, ours) widens it by the light's half-vector
// cone, whose radius is tan(rho / 2) in slope units for a light of angular
// radius rho: an explicit facet stays lit while its normal is inside that
// cone, so the counts keep their draw while the half vector moves within
// it (in quadrature with R: a point light keeps R). Each frame's law is
// unchanged (same p, same uniforms' law); only which half vectors share a
// draw changes. docs/MODELS.md kneiphof2025, "Angular lifetime".
float kneiphof2025_area_grid_roughness(float cos_max, float microfacet_roughness,
                                       bool light_sized_grid) {
    if (!light_sized_grid) return microfacet_roughness;
    float c = clamp(cos_max, -1.0f, 1.0f);
    // tan(acos(c) / 2) = sqrt((1 - c) / (1 + c)), at most 1 (a light over a
    // hemisphere or more).
    float t_half = min(sqrt((1.0f - c) / max(1.0f + c, 1e-12f)), 1.0f);
    return sqrt(microfacet_roughness * microfacet_roughness + t_half * t_half);
}

// The area light's glint radiance (K = 1, kneiphof2024 / 003 Eq. 6-9, 23):
// the smooth radiance of the cone times b / (E[N_P] p). Visibility is the
// caller's (one shadow test towards the axis).
vec3 kneiphof2025_area_light(vec3 axis, float cos_max, vec3 radiance, vec3 t, vec3 b, vec3 n,
                             vec3 wo, float alpha, vec3 f0, vec3 color, Footprint fp,
                             float log_density, uint seed, float microfacet_roughness,
                             bool light_sized_grid, float screen_space_scale,
                             float density_randomization, bool conditional) {
    float p = 0.0f;
    vec3 h_center = vec3(0.0f, 0.0f, 1.0f);
    vec3 L = kneiphof2025_integrate_cone(axis, cos_max, radiance, t, b, n, wo, alpha, f0, color, p,
                                         h_center);
    if ((L.x == 0.0f && L.y == 0.0f && L.z == 0.0f) || h_center.z <= 0.0f) return vec3(0.0f);
    float grid_r =
        kneiphof2025_area_grid_roughness(cos_max, microfacet_roughness, light_sized_grid);
    return L * kneiphof2025_area_factor(h_center, fp, p, log_density, seed, grid_r,
                                        screen_space_scale, density_randomization, conditional);
}

// The direction at which the prefiltered maps are read: the split-sum kernel
// assumes n = v = r (Eq. 11), which puts too much of a rough lobe around the
// mirror direction r; Lagarde & de Rousiers 2014 ([LDR14], whose prefiltering
// 003 follows) read at the lobe's dominant direction, bent from r towards n:
// lerp(n, r, s (sqrt(s) + alpha)), s = 1 - alpha. On the validation sphere
// this cut the split-sum's per-pixel error at sqrt(alpha) = 0.5-0.7 from up
// to +50 % (+250 % near the lower silhouette) to ~15 % (docs/MODELS.md).
// The same direction serves the radiance and the weight maps (Eq. 21 reuses
// the kernel of Eq. 11).
vec3 kneiphof2025_lookup_direction(vec3 n, vec3 wr, float alpha) {
    float s = clamp(1.0f - alpha, 0.0f, 1.0f);
    float f = s * (sqrt(s) + alpha);
    return normalize(n + (wr - n) * f);
}

// The smooth radiance L_o of Eq. 11 (the term the glint factor multiplies).
//  - SPLIT_SUM ("as_published", 003): E_rho(wo) times the prefiltered
//    radiance at the lookup direction, whose kernel assumes n = v = r.
//  - LOBE_SUN (default; docs/MODELS.md): LOBE below on the radiance without
//    the environment's bright sources, plus the sources by the BRDF at
//    KNEIPHOF2025_SOURCES directions inside them
//    (kneiphof2025_sources_radiance). With the sources in the maps, 32
//    samples reading GGX-blurred levels are a kernel estimate of the lobe
//    whose heavy tails and gaps put +14-18 % on a sphere lit by a low sun
//    (sunrise.exr; 256 samples would be needed for 4 %) and +300 % on a
//    plane at grazing view under small lamps near the horizon (studio.exr).
//  - LOBE (an option; an improvement over 003, docs/MODELS.md): E_rho(wo) times
//    the radiance averaged over the true reflection lobe of wo, estimated by
//    filtered importance sampling (Colbert & Krivanek, GPU Gems 3 ch. 20) of
//    the same prefiltered maps. The split sum's kernel ignores the lobe's
//    stretching at oblique views and its clipping by the horizon: on the
//    003 Fig. 6 sphere at sqrt(alpha) = 0.7 its image mean is 6.7 % off the
//    exact integral (+18 % near the silhouette), the lobe estimate's 2.2 %
//    (docs/VALIDATION.md).
const int KNEIPHOF2025_SMOOTH_SPLIT_SUM = 0;
const int KNEIPHOF2025_SMOOTH_LOBE = 1;
const int KNEIPHOF2025_SMOOTH_LOBE_SUN = 2;
const int KNEIPHOF2025_LOBE_SAMPLES = 32;

// The lobe's mean radiance sum_j G2_j L(wi_j) / sum_j G2_j over visible
// normals h_j ~ G1(wo) <wo, h> D(h) / cos_o (Heitz 2018): wi_j = reflect(wo, h_j)
// has pdf G1(wo) D(h) / (4 cos_o) and weight F G2 / G1(wo); the constant
// G1(wo) cancels in the ratio, and F is left to E_rho, so a constant
// environment stays exact (the furnace). Samples below the horizon have
// G2 = 0: the clipping the split sum misses.
// Sample positions: a Fibonacci lattice ((j + 1/2) / M, frac(j / phi)), the
// same for every pixel (a smooth, noise-free term). Each sample reads the
// level whose GGX kernel (solid angle ~ 4 pi alpha_l^2 at n = v = r) covers its
// share of the lobe, 1 / (M pdf), capped at the lobe's own roughness.
// Measured on the validation sphere (docs/VALIDATION.md): M = 32 halves the
// error of M = 16 at sqrt(alpha) >= 0.5; more blur per sample (4x the solid
// angle) biases the centre of the sphere upwards by up to 28 % under a sun
// (GGX kernel tails), and a 2 x 2 box pyramid instead of the GGX levels
// aliases the suns (-10 %).
// `residual`: read the radiance without the sources, max(rgb - w color, 0)
// of kneiphof2025_radiance_sources_fetch (exact in luminance; the sources'
// texels are taken to share their mean colour).
vec3 kneiphof2025_lobe_fetch(vec3 dir, float level, bool residual, vec3 sources_color) {
    if (!residual) return kneiphof2025_radiance_fetch(dir, level);
    vec4 r = kneiphof2025_radiance_sources_fetch(dir, level);
    return max(vec3(r.x, r.y, r.z) - r.w * sources_color, vec3(0.0f));
}
vec3 kneiphof2025_lobe_radiance_of(vec3 n, vec3 wr, float cos_o, float alpha, bool residual,
                                   vec3 sources_color) {
    vec3 t;
    vec3 b;
    tangent_frame(n, t, b);
    vec3 wo_world = 2.0f * cos_o * n - wr;
    vec3 wo = normalize(vec3(dot(wo_world, t), dot(wo_world, b), max(cos_o, 1e-4f)));
    float roughness = sqrt(alpha);
    // What every sample shares, computed once (the lobe is
    // arithmetic-bound on a GPU): G1(wo)'s Lambda, and the visible-normal
    // sampler's frame. The same operations as G1_Smith, G2_SmithCorrelated
    // and sample_vndf_ggx, so the values are theirs.
    float lambda_o = Lambda_Microfacet(NDF_GGX, wo, alpha, alpha);
    float g1 = 1.0f / (1.0f + lambda_o);
    VndfGgxFrame frame = vndf_ggx_frame(wo, alpha, alpha);
    vec3 sum = vec3(0.0f);
    float weight = 0.0f;
    for (int j = 0; j < KNEIPHOF2025_LOBE_SAMPLES; ++j) {
        float fj = float(j);
        vec2 u = vec2((fj + 0.5f) / float(KNEIPHOF2025_LOBE_SAMPLES), fract(fj * 0.6180339887f));
        vec3 h = sample_vndf_ggx_in(frame, alpha, alpha, u);
        float oh = dot(wo, h);
        if (!(oh > 0.0f)) continue;
        vec3 wi = 2.0f * oh * h - wo;
        if (!(wi.z > 0.0f)) continue;
        float g2 = 1.0f / (1.0f + lambda_o + Lambda_Microfacet(NDF_GGX, wi, alpha, alpha));
        float pdf = g1 * D_Microfacet(NDF_GGX, h, alpha, alpha) / (4.0f * wo.z);
        float omega = 1.0f / (float(KNEIPHOF2025_LOBE_SAMPLES) * max(pdf, 1e-6f));
        float level = min(sqrt(sqrt(omega / (4.0f * PI))), roughness);
        sum += g2 * kneiphof2025_lobe_fetch(wi.x * t + wi.y * b + wi.z * n, level, residual,
                                            sources_color);
        weight += g2;
    }
    if (!(weight > 0.0f))
        return kneiphof2025_lobe_fetch(kneiphof2025_lookup_direction(n, wr, alpha), roughness,
                                       residual, sources_color);
    return sum / weight;
}
vec3 kneiphof2025_lobe_radiance(vec3 n, vec3 wr, float cos_o, float alpha) {
    return kneiphof2025_lobe_radiance_of(n, wr, cos_o, alpha, false, vec3(0.0f));
}

// The sources' reflected radiance: the smooth BRDF at each source direction
// times its power, F G2 D(h) / (4 cos_o) Phi (F Schlick's with f0, as the
// split sum's E_rho), 0 below the horizon. The solid angle a direction
// stands for (angular radius r) widens the GGX lobe to
// alpha' = sqrt(alpha^2 + r^2 / 4) (the half vector moves by half the light
// direction's angle), which keeps D's integral and spreads a mirror's
// reflection of a lamp over the lamp instead of a pattern of dots.
vec3 kneiphof2025_sources_radiance(vec3 n, vec3 wr, float cos_o, float alpha, vec3 f0) {
    int count = kneiphof2025_source_count();
    if (count == 0) return vec3(0.0f);
    vec3 t;
    vec3 b;
    tangent_frame(n, t, b);
    vec3 wo_world = 2.0f * cos_o * n - wr;
    vec3 wo = normalize(vec3(dot(wo_world, t), dot(wo_world, b), max(cos_o, 1e-4f)));
    vec3 sum = vec3(0.0f);
    for (int k = 0; k < count; ++k) {
        vec3 dir;
        vec3 power;
        float radius;
        kneiphof2025_source(k, dir, power, radius);
        vec3 wi = vec3(dot(dir, t), dot(dir, b), dot(dir, n));
        if (!(wi.z > 0.0f)) continue;
        vec3 h = normalize(wo + wi);
        float a_k = min(sqrt(alpha * alpha + 0.25f * radius * radius), 1.0f);
        float d = D_Microfacet(NDF_GGX, h, a_k, a_k);
        float g2 = G2_SmithCorrelated(NDF_GGX, wo, wi, alpha, alpha);
        vec3 f = F_Schlick(f0, max(dot(wo, h), 0.0f));
        sum += f * (g2 * d / (4.0f * wo.z)) * power;
    }
    return sum;
}

// L_o of Eq. 11 (see the SMOOTH constants above); color and F0 enter through
// E_rho = color (F0 A + B), dfg = kneiphof2025_dfg_fetch(cos_o, sqrt(alpha))
// (the caller's, which also needs E_D / D_H).
vec3 kneiphof2025_smooth_radiance(vec3 n, vec3 wr, float cos_o, float alpha, vec3 f0, vec3 color,
                                  vec3 dfg, int smooth_mode) {
    float roughness = sqrt(clamp(alpha, 0.0f, 1.0f));
    vec3 e_rho = color * (f0 * dfg.x + vec3(dfg.y));  // Eq. 11, first integral
    if (smooth_mode == KNEIPHOF2025_SMOOTH_LOBE_SUN) {
        vec3 residual = kneiphof2025_lobe_radiance_of(n, wr, cos_o, alpha, true,
                                                      kneiphof2025_sources_color());
        return e_rho * residual + color * kneiphof2025_sources_radiance(n, wr, cos_o, alpha, f0);
    }
    vec3 radiance =
        smooth_mode == KNEIPHOF2025_SMOOTH_LOBE
            ? kneiphof2025_lobe_radiance(n, wr, cos_o, alpha)
            : kneiphof2025_radiance_fetch(kneiphof2025_lookup_direction(n, wr, alpha), roughness);
    return e_rho * radiance;
}

// Environment lighting of one footprint (Eq. 11, 15, 17, 21).
// n, wr: world normal and mirror direction of wo; cos_o = n.wo > 0; alpha = GGX roughness;
// f0: Schlick reflectance at normal incidence (split-sum E_rho = F0 A + B);
// levels K (4 or 8) and radiance levels L_a (k = 1-4), L_b (k = 5-8);
// variant: ours, or the wang2020 style with a fixed cone of solid angle
// gamma_solid_angle around the mirror direction; conditional: the Gaussian
// moments of binomial_dual_gated_conditional instead of Algorithm 1's;
// smooth_mode: KNEIPHOF2025_SMOOTH_SPLIT_SUM, _LOBE or _LOBE_SUN (the smooth term).
vec3 kneiphof2025_environment(vec3 n, vec3 wr, float cos_o, float alpha, vec3 f0, vec3 color,
                              Footprint fp, float log_density, uint seed, float screen_space_scale,
                              float density_randomization, int levels, vec4 L_a, vec4 L_b,
                              int variant, float gamma_solid_angle, bool conditional,
                              int smooth_mode) {
    float roughness = sqrt(clamp(alpha, 0.0f, 1.0f));
    vec3 dir = kneiphof2025_lookup_direction(n, wr, alpha);
    vec3 dfg = kneiphof2025_dfg_fetch(cos_o, roughness);
    vec3 smooth_radiance =
        kneiphof2025_smooth_radiance(n, wr, cos_o, alpha, f0, color, dfg, smooth_mode);
    float factor;
    if (variant == KNEIPHOF2025_VARIANT_WANG2020) {
        // 003 Fig. 8: p from a user cone, not from the environment. We take the
        // probability of the facets within the cone Omega_gamma around the
        // mirror direction, p = D(n) Omega_gamma / (4 cos_o D_H) (Eq. 8-9 with
        // h = n), capped by the visible reflecting area.
        float d_n = 1.0f / (PI * alpha * alpha);
        float p = min(
            d_n * gamma_solid_angle / (4.0f * cos_o * kneiphof2025_total_facet_area(alpha)), dfg.z);
        factor = kneiphof2025_binomial_factor_no_h(fp, p, log_density, seed, screen_space_scale,
                                                   density_randomization, conditional);
    } else {
        vec4 w_a = kneiphof2025_weights_fetch(dir, roughness, 0);
        vec4 w_b = levels > 4 ? kneiphof2025_weights_fetch(dir, roughness, 1) : vec4(0.0f);
        vec4 p_a;
        vec4 p_b;
        kneiphof2025_probabilities(w_a, w_b, levels, dfg.z, p_a, p_b);
        factor =
            kneiphof2025_ibl_factor(fp, log_density, seed, screen_space_scale,
                                    density_randomization, levels, p_a, p_b, L_a, L_b, conditional);
    }
    return smooth_radiance * factor;
}

#endif
