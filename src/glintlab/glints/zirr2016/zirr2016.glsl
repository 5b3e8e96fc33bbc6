// zirr2016 footprint NDF D_P(h): Zirr & Kaplanyan, "Real-time Rendering of
// Procedural Multiscale Materials", I3D 2016 ([ZK16]), implemented as
// restated by Deliot & Belcour 2023 (000, deliot2023) §3 (Eq. 3-7), §5
// (Eq. 11: square mip grids), §6.3 (Eq. 15) and §7 (anisotropy clamped at
// x16), and by Chermain et al. 2020 (004, chermain2020) §2 (MIP
// hierarchy walked over the footprint's cells, binomial count per cell).
// Equation numbers below are 000's unless marked 004.
//
// Pipeline for one half vector h and one pixel footprint:
//  1. footprint ellipse (minor, major, direction); the ratio is clamped to
//     max_anisotropy by widening the minor axis (the footprint grows
//     isotropically, 000 §7 / Fig. 11: the baseline's stretched glints);
//  2. continuous LOD = log2(minor x S) between two square mip grids
//     (Eq. 11), levels l0 = floor(LOD) and l0 + 1, weight w = fract(LOD);
//  3. footprint marching: ceil(major / minor) sample points along the major
//     axis, each in the texel containing it at both levels (004 §2);
//  4. per texel: N = density x texel area trials, an angular grid over
//     h.xy / R with a per-texel random offset, blended bilinearly (§3
//     "Temporal Coherence"); 4 counts from the law of Eq. 15;
//  5. the two levels' counts are blended by output (Eq. 7) and
//     D_P = D(n) / R x count / trials (Eq. 3-4).
// Kept as the baseline: output blending (wrong count statistics mid-LOD,
// Fig. 4b), the floored Gaussian of Eq. 15 (mean N p - 1/2), a cost that
// grows with anisotropy (up to 2 x 64 x 4 laws) and with N (up to 16 trials).
#ifndef GLINTLAB_GLINTS_ZIRR2016_GLSL
#define GLINTLAB_GLINTS_ZIRR2016_GLSL

#include "glintlab/core/constants.glsl"
#include "glintlab/core/footprint.glsl"
#include "glintlab/core/hash.glsl"
#include "glintlab/counting/binomial_laws.glsl"
#include "glintlab/microfacet/ndf.glsl"

// LOD range: texels from 2^-24 (fp32 resolution of uv in [0, 1]) to 2^24.
const float ZIRR2016_MAX_ABS_LOD = 24.0f;
// Loop bound of the footprint march: the largest max_anisotropy allowed.
const int ZIRR2016_MAX_STEPS = 64;
// ln of the largest trial count (e^80 ~ 5.5e34: 2 x 64 texels still sum
// below FLT_MAX).
const float ZIRR2016_MAX_LOG_TRIALS = 80.0f;
// Texel indices wrap with period 2^20 so float to int conversions stay in range.
const int ZIRR2016_LATTICE_MASK = 1048575;
const float ZIRR2016_LATTICE_PERIOD = 1048576.0f;
const float ZIRR2016_LN2 = 0.69314718f;

// Axes of the footprint ellipse of J = (dx dy): (minor, major, angle of the
// major axis). Eigenvalues of J J^T; minor = |det J| / major avoids the
// cancellation of the closed form for elongated footprints.
vec3 zirr2016_footprint_axes(vec2 dx, vec2 dy) {
    float m = max(max(abs(dx.x), abs(dx.y)), max(abs(dy.x), abs(dy.y)));
    if (!(m > 0.0f)) return vec3(0.0f);
    dx = dx / m;
    dy = dy / m;
    float a = dx.x * dx.x + dy.x * dy.x;
    float b = dx.x * dx.y + dy.x * dy.y;
    float c = dx.y * dx.y + dy.y * dy.y;
    float half_diff = 0.5f * (a - c);
    float major = sqrt(0.5f * (a + c) + sqrt(half_diff * half_diff + b * b));
    float minor = abs(dx.x * dy.y - dx.y * dy.x) / major;
    float angle = (b != 0.0f || half_diff != 0.0f) ? 0.5f * atan(2.0f * b, a - c) : 0.0f;
    return vec3(minor * m, major * m, angle);
}

// Eq. 15 count in one angular cell of one texel, with the cell's uniforms
// drawn from its hash: 1 for the Gaussian, then as many as the Bernoulli sum
// reads (ceil(N) <= 16; none when N p > 5).
// binomial_zirr2016 (counting/binomial_laws.glsl) with its trials drawn and
// counted in one loop, without the 4 x 4 matrix of uniforms (a dynamically
// indexed local array, which shader compilers keep in scratch memory): the
// same draws compared with the same q, so the same counts bit for bit.
float zirr2016_cell_law(float N, float p, uint cell_hash) {
    uint s = cell_hash;
    float xi_gauss = hash_random(s);
    float n = max(N, 0.0f);
    if (n * p > 5.0f) {
        return clamp(floor(gaussian_deviate(n * p, n * p * (1.0f - p), xi_gauss)), 0.0f, n);
    }
    int trials = int(min(ceil(n), 16.0f));
    float q = trials > 0 ? n * p / float(trials) : 0.0f;
    float count = 0.0f;
    // do-while loops here and below: a for loop costs SIMD back ends one
    // masked pass more (docs/ARCHITECTURE.md, "Writing shared code that SIMD
    // back ends run fast").
    if (trials > 0) {
        int k = 0;
        do {
            count += hash_random(s) < q ? 1.0f : 0.0f;
            ++k;
        } while (k < trials);
    }
    return count;
}

// Count of one texel (level l, index t): the 4 angular cells around
// `slope` (h.xy / R, offset per texel), blended bilinearly (000 §3).
float zirr2016_texel_count(ivec2 t, int l, vec2 slope, float N, float p, uint seed) {
    uint ts = hash_cell3(ivec3(t & ivec2(ZIRR2016_LATTICE_MASK), l), seed);
    // Sequenced draws: C++ leaves the order of constructor arguments
    // unspecified, GLSL evaluates left to right (CPU and GPU must agree).
    float offset_x = hash_random(ts);
    float offset_y = hash_random(ts);
    vec2 a = mod(slope + vec2(offset_x, offset_y), ZIRR2016_LATTICE_PERIOD);
    vec2 af = floor(a);
    ivec2 ac = ivec2(af);
    vec2 f = clamp(a - af, 0.0f, 1.0f);
    float count = 0.0f;
    int c = 0;
    do {
        ivec2 corner = ac + ivec2(c & 1, c >> 1);
        float wc = ((c & 1) == 1 ? f.x : 1.0f - f.x) * ((c >> 1) == 1 ? f.y : 1.0f - f.y);
        if (!(wc <= 0.0f))
            count +=
                wc * zirr2016_cell_law(N, p, hash_cell(corner & ivec2(ZIRR2016_LATTICE_MASK), ts));
        ++c;
    } while (c < 4);
    return count;
}

// Index of the level-l texel (side 2^l uv units) that contains uv.
ivec2 zirr2016_texel(vec2 uv, int l) {
    return ivec2(floor(mod(uv * exp2(-float(l)), ZIRR2016_LATTICE_PERIOD)));
}

// D_P(h) of Eq. 3-4 for a local half vector h (z = normal) and a uv footprint.
// ndf, alpha_x, alpha_y, rho: target NDF D (rho: its slopes' correlation, a
// footprint's sheared lobe; the angular grid stays on the frame's axes);
// log_density: ln(facets per unit uv area); seed: the material's seed; microfacet_roughness = R in (0, 1]
// (angular cell size in slope units); max_anisotropy in [1, 64];
// screen_space_scale S: texel width in footprint minor widths.
float zirr2016_ndf(vec3 h, Footprint fp, int ndf, float alpha_x, float alpha_y, float rho,
                   float log_density, uint seed, float microfacet_roughness, float max_anisotropy,
                   float screen_space_scale) {
    float d_h = D_Microfacet_correlated(ndf, h, alpha_x, alpha_y, rho);
    if (!(d_h > 0.0f)) return 0.0f;
    // max of D
    float d_n = D_Microfacet_correlated(ndf, vec3(0.0f, 0.0f, 1.0f), alpha_x, alpha_y, rho);
    float R = microfacet_roughness;
    float p = clamp(R * d_h / d_n, 0.0f, 1.0f);  // Eq. 4 success probability

    vec3 axes = zirr2016_footprint_axes(fp.duvdx, fp.duvdy);
    float major = max(axes.y, 1e-30f);
    float aniso = clamp(max_anisotropy, 1.0f, float(ZIRR2016_MAX_STEPS));
    float minor = max(axes.x, major / aniso);  // anisotropy clamp (000 §7)
    int steps = clamp(int(ceil(major / minor - 1e-3f)), 1, ZIRR2016_MAX_STEPS);

    // Eq. 7 levels: bottom l0 (texels <= footprint), top l0 + 1, weight w of the top.
    float lod = clamp(log2(max(minor * screen_space_scale, 1e-30f)), -ZIRR2016_MAX_ABS_LOD,
                      ZIRR2016_MAX_ABS_LOD);
    int l0 = int(floor(lod));
    float w = lod - float(l0);
    // Trials per texel: density x texel area 2^(2l) (004 §2).
    float log_bottom = log_density + float(2 * l0) * ZIRR2016_LN2;
    float n_bottom = exp(clamp(log_bottom, -ZIRR2016_MAX_LOG_TRIALS, ZIRR2016_MAX_LOG_TRIALS));
    float n_top = exp(
        clamp(log_bottom + 2.0f * ZIRR2016_LN2, -ZIRR2016_MAX_LOG_TRIALS, ZIRR2016_MAX_LOG_TRIALS));

#ifdef GLINTLAB_ZIRR2016_EXPECTATION_EXIT
    // GPU glue: where the footprint's 2 x 4 x steps angular cells hold fewer
    // than 2^-24 expected successes in all (each cell N p, Eq. 15's Bernoulli
    // regime), every count is 0 but with a probability below 2^-24: D_P = 0,
    // as the CPU draws it, and the march is skipped. (Returning the mean D(h)
    // drew a smooth highlight below one facet per unit uv area, where the
    // CPU's counts are black.)
    if (8.0f * float(steps) * max(n_bottom, n_top) * p < 5.9604645e-8f) return 0.0f;
#endif

    vec2 slope = vec2(h.x, h.y) / R;
    vec2 dir = vec2(cos(axes.z), sin(axes.z));
    float count = 0.0f;
    int k = 0;
    do {  // steps >= 1
        vec2 uv = fp.uv + dir * (major * ((float(k) + 0.5f) / float(steps) - 0.5f));
        float c_bottom = 0.0f;
        float c_top = 0.0f;
        if (w < 1.0f) {
            c_bottom = zirr2016_texel_count(zirr2016_texel(uv, l0), l0, slope, n_bottom, p, seed);
        }
        if (w > 0.0f) {
            c_top = zirr2016_texel_count(zirr2016_texel(uv, l0 + 1), l0 + 1, slope, n_top, p, seed);
        }
        count += mix(c_bottom, c_top, w);  // Eq. 7: output blending
        ++k;
    } while (k < steps);
    float trials = float(steps) * mix(n_bottom, n_top, w);
    // Eq. 3-4: D(n)/R x count/trials, whose mean is D(h) up to Eq. 15's floor (Eq. 5-6).
    return trials > 0.0f ? d_n / R * (count / trials) : d_h;
}

#endif
