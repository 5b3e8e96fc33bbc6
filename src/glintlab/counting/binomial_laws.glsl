// Approximate binomial laws b(N, p) of the real-time glint models. Each law is
// a pure function of (N, p) and uniform numbers in [0, 1); the gated laws
// cost the same for every N and p (no loop over trials).
//
// Papers: 000 = Deliot & Belcour 2023, 003 = Kneiphof & Klein 2025 (key and full citations: docs/MODELS.md).
// Counts are real-valued where the paper's law is (003 drops the floor of
// Eq. 22 for N > 1); consumers that need integers round them.
#ifndef GLINTLAB_COUNTING_BINOMIAL_LAWS_GLSL
#define GLINTLAB_COUNTING_BINOMIAL_LAWS_GLSL

#include "glintlab/counting/normal_quantile.glsl"
#include "glintlab/microfacet/erf.glsl"

// epsilon = 10^-3.54 of 003 §6 "Numeric Gating Issues", found optimal there
// for fp32 over (N, p) in [1, 1e16] x [1e-16, 1].
const float STABLE_POW_EPSILON = 2.8840315e-4f;

// The naive fp32 evaluation of (1 - p)^N: for p below ~6e-8, 1 - p rounds
// to 1 and the result is 1 whatever N (003 Fig. 5b).
float pow_one_minus_naive(float p, float N) {
    return N > 0.0f ? pow(max(1.0f - p, 0.0f), N) : 1.0f;
}

// x^y for x in [0, 1], y > 0, as GLSL defines pow (exp2(y log2 x)), with
// results below 2^-126 flushed to 0 (x = 0 included: log2(0) = -inf). This
// keeps the CPU path off libm's slow underflow branch, so the cost no longer
// depends on N, and changes no gate: such probabilities are 0 next to the
// 2^-24 resolution of a uniform.
float pow_unit(float x, float y) {
    float e = y * log2(x);
    return e > -126.0f ? exp2(e) : 0.0f;
}

// The scale c = max(1, epsilon / p) of 003 Eq. 25. p is floored at 1e-30 so
// that p = 0 gives a finite c (then c * p = 0 and the power is exactly 1).
float stable_pow_scale(float p) {
    return max(1.0f, STABLE_POW_EPSILON / max(p, 1e-30f));
}

// (1 - p)^N ~= (1 - c p)^(N / c), 003 Eq. 24-25: for p < epsilon the base is
// 1 - epsilon, which fp32 represents to 2e-4 relative accuracy.
float pow_one_minus_stable(float p, float N) {
    float c = stable_pow_scale(p);
    return N > 0.0f ? pow_unit(max(1.0f - c * p, 0.0f), N / c) : 1.0f;
}

// A Gaussian deviate N(mean, variance) from the standard normal deviate z.
float gaussian_from_standard(float mean, float variance, float z) {
    return mean + sqrt(max(variance, 0.0f)) * z;
}
// A Gaussian deviate N(mean, variance) from one uniform number.
float gaussian_deviate(float mean, float variance, float xi) {
    return gaussian_from_standard(mean, variance, normal_quantile(xi));
}

// Law 2: the plain Gaussian approximation with the binomial's first two
// moments (000 §6.3 "Classical Binomial Approximation"), clamped to [0, N].
float binomial_gaussian(float N, float p, float xi) {
    float n = max(N, 0.0f);
    return clamp(gaussian_deviate(n * p, n * p * (1.0f - p), xi), 0.0f, n);
}

// Law 3: zirr2016 as restated in 000 Eq. 15. Gaussian (floored, as written)
// when N p > 5, else an explicit sum of Bernoulli trials, at most 16 as in
// their implementation (000 §7.1). Eq. 15 writes H(theta_k - p); a trial
// succeeds with probability p, so we count theta_k < p. For N > 16 the paper
// does not say how 16 trials stand for N: we use ceil(N) <= 16 trials of
// probability N p / ceil(N), which keeps the mean N p and is the exact law for
// integer N <= 16. The loop length grows with N: this law is not constant-cost.
float binomial_zirr2016(float N, float p, float xi_gauss, mat4 xi_trials) {
    float n = max(N, 0.0f);
    if (n * p > 5.0f) {
        return clamp(floor(gaussian_deviate(n * p, n * p * (1.0f - p), xi_gauss)), 0.0f, n);
    }
    int trials = int(min(ceil(n), 16.0f));
    float q = trials > 0 ? n * p / float(trials) : 0.0f;
    float count = 0.0f;
    for (int k = 0; k < trials; ++k) {
        count += xi_trials[k / 4][k % 4] < q ? 1.0f : 0.0f;
    }
    return count;
}

// Law 4: deliot2023's gated Gaussian, 000 Eq. 16-18. Gate on
// P(>=1) = 1 - (1 - p)^N (Eq. 16, in the stable form of 003 Eq. 25), then one
// success plus a Gaussian for the N - 1 remaining trials (Eq. 17), floored
// (Eq. 18). Eq. 18 writes H(theta_0 - P); the gate passes with probability P,
// so we test theta_0 < P. The Gaussian is clamped to the N - 1 remaining
// trials (a fix the authors' HLSL lacked: docs/MODELS.md, "Known defects of the
// original HLSL"). Kept as
// published for N < 1: the gate then overestimates P(count >= 1), since
// 1 - (1 - p)^N > N p there (the defect 003 Appendix B fixes).
float binomial_deliot2023(float N, float p, float xi0, float xi1) {
    float n = max(N, 0.0f);
    float p_any = 1.0f - pow_one_minus_stable(p, n);
    float rest = max(n - 1.0f, 0.0f);
    float g = clamp(gaussian_deviate(rest * p, rest * p * (1.0f - p), xi1), 0.0f, rest);
    return xi0 < p_any ? floor(1.0f + g) : 0.0f;
}

// Law 5: kneiphof2025's single-gated Gaussian for real N >= 0, 003 Eq. 23:
// gate probability min(N p, P(>=1)) (= N p for N < 1, Appendix B), then
// Phi^-1(xi2; 1 + (N - 1) p, (N - 1) p (1 - p)) clamped to [1, max(N, 1)],
// i.e. the Gaussian part is clamped to the N - 1 remaining trials.
// Split into the part that depends on (N, p) only and the draw, so that a
// caller drawing several counts of one (N, p) (deliot2023's 4 angular
// corners of a vertex) computes the gate's power once; the same operations
// in the same order, so the counts are bit for bit those of the one-call form.
struct SingleGatedLaw {
    float p_gate;  // min(N p, P(>=1))
    float mean;    // 1 + (N - 1) p
    float sd;      // sqrt((N - 1) p (1 - p))
    float top;     // max(N, 1)
    float scale;   // 1 here; the conditional form's mean correction (Law 5b)
};
// (binomial_single_gated_law: below, with its conditional form.)
// The gate first: a closed gate returns 0 without the normal
// quantile, the same value as evaluating both and selecting; where the gates
// of a pixel block are closed (sparse footprints, the NDF's tails) the block
// skips the quantile.
float binomial_single_gated_draw(SingleGatedLaw law, float xi1, float xi2) {
    if (!(xi1 < law.p_gate)) return 0.0f;
    float g = law.mean + law.sd * normal_quantile(xi2);
    return clamp(g, 1.0f, law.top) * law.scale;
}

// Standard normal CDF from the shared erf (absolute error < 1e-7).
float standard_normal_cdf(float x) {
    return 0.5f + 0.5f * erf_approx(x * 0.70710678f);
}

// E[clamp(X, lo, hi)] for X ~ N(mean, sd^2), lo <= mean <= hi, lo < hi:
//   mean + sd (phi(a) + a Phi(a)) - sd (phi(b) - b (1 - Phi(b))),
// a = (lo - mean) / sd, b = (hi - mean) / sd (the two terms are E[(lo - X)+]
// and E[(X - hi)+]); mean is clamped to [lo, hi] first, so a <= 0 <= b, and
// a, b are kept within 40 of 0, where both terms are 0 in fp32 (sd -> 0 and
// hi = 1e35 stay finite).
// A bound 6 or more standard deviations away contributes 0 (the GPU cost of
// the conditional law is these erf and exp, which every vertex of a dense
// footprint would evaluate for nothing): there the term is below
// phi(6) / 36 = 1.7e-10 (phi(a) + a Phi(a) < phi(a) / a^2), while its fp32
// evaluation is the difference of two numbers ~1e-9 carrying erf_approx's
// absolute error 1e-7 times |a|, so 0 is the closer value.
const float CLAMPED_GAUSSIAN_NEGLIGIBLE_TAIL = 6.0f;
float clamped_gaussian_mean(float mean, float sd, float lo, float hi) {
    mean = clamp(mean, lo, hi);
    if (!(sd > 0.0f)) return mean;
    const float inv_sqrt_2pi = 0.39894228f;
    float a = clamp((lo - mean) / sd, -40.0f, 0.0f);
    float b = clamp((hi - mean) / sd, 0.0f, 40.0f);
    float below = 0.0f;
    float above = 0.0f;
    if (a > -CLAMPED_GAUSSIAN_NEGLIGIBLE_TAIL)
        below = inv_sqrt_2pi * exp(-0.5f * a * a) + a * standard_normal_cdf(a);
    if (b < CLAMPED_GAUSSIAN_NEGLIGIBLE_TAIL)
        above = inv_sqrt_2pi * exp(-0.5f * b * b) - b * standard_normal_cdf(-b);
    return mean + sd * (max(below, 0.0f) - max(above, 0.0f));
}

// Law 5b (an extension, not in 000 or 003; deliot2023's and kneiphof2025's
// `"gaussian": "conditional"`, their default): Law 5's gate, then a Gaussian
// with the moments of b(N, p) conditioned on the gate, clamped to
// [1, max(N, 1)] and rescaled so that its mean is the conditional mean
// exactly. Law 5 centres the Gaussian on 1 + (N - 1) p ("one success, N - 1
// free trials"), which is the conditional mean only when the gate is sure:
// E[count] / (N p) - 1 is +31 % at N p = 1-2 (p = 0.025; +11 % at N p = 0.1,
// +10 % at N p = 10). With the gate g = min(N p, P(>=1)) (P(>=1) = 1 - (1 - p)^N):
//   mu  = E[n | gate] = N p / g,
//   var = E[n^2] / g - mu^2 = mu ((1 - p) - (mu - N p))   (E[n^2] = N p (1 - p) + (N p)^2),
// (for N < 1, g = N p, mu = 1 and the count is 1: 003 Appendix B's law). The
// clamp to [1, N] alone would still add up to +8 % (N p ~ 0.5: a Gaussian of
// mean 1.3 and sd 0.6 piled up at 1), hence the factor
// scale = mu / E[clamped Gaussian] (<= 1, clamped_gaussian_mean):
// E[count] = g scale E[clamped] = g mu = N p for every real N >= 0 and p
// (CountingLaws.ConditionalSingleGatedIsUnbiased); the variance is the
// conditional one up to the clamp and the factor. Same draw as Law 5
// (binomial_single_gated_draw): the extra cost is per (N, p), not per count.
//
// Law 5 and Law 5b in one function: the gate (its power) is the same, the
// Gaussian's mean, sd and scale are chosen after it, so a caller choosing
// between the laws does not evaluate both (SIMD back ends such as llvmpipe
// run both sides of such a choice; per vertex in deliot2023, where it made
// no measurable difference). The operations on the values are those of
// each law as written (SingleGatedLaw.BothFormsAsWritten).
SingleGatedLaw binomial_single_gated_law_of(float N, float p, bool conditional) {
    float n = max(N, 0.0f);
    float np = n * p;
    SingleGatedLaw law;
    law.p_gate = min(np, 1.0f - pow_one_minus_stable(p, n));
    law.top = max(n, 1.0f);
    // Law 5 (003 Eq. 23): one success, N - 1 free trials.
    float rest = max(n - 1.0f, 0.0f);
    law.mean = 1.0f + rest * p;
    law.sd = sqrt(max(rest * p * (1.0f - p), 0.0f));
    law.scale = 1.0f;
    if (conditional && law.p_gate > 0.0f) {
        float mu = clamp(np / law.p_gate, 1.0f, law.top);
        law.mean = mu;
        law.sd = sqrt(max(mu * ((1.0f - p) - (mu - np)), 0.0f));
        law.scale = mu / clamped_gaussian_mean(mu, law.sd, 1.0f, law.top);
    } else if (conditional) {
        law.mean = 1.0f;
        law.sd = 0.0f;
    }
    return law;
}
SingleGatedLaw binomial_single_gated_law(float N, float p) {
    return binomial_single_gated_law_of(N, p, false);
}
SingleGatedLaw binomial_single_gated_conditional_law(float N, float p) {
    return binomial_single_gated_law_of(N, p, true);
}
float binomial_single_gated_conditional(float N, float p, float xi1, float xi2) {
    return binomial_single_gated_draw(binomial_single_gated_conditional_law(N, p), xi1, xi2);
}
float binomial_single_gated(float N, float p, float xi1, float xi2) {
    return binomial_single_gated_draw(binomial_single_gated_law(N, p), xi1, xi2);
}

// Law 6: kneiphof2025's dual-gated Gaussian, 003 Algorithm 1. Returns
// (n, nbar): positive and negative samples. One uniform (xi1) makes every
// gating decision, xi2 drives the Gaussian. Line 6 is garbled in the text;
// read as in the authors' code, it is P(nbar = N) = clamp(N - 1, 0, 1) (1 - c p)^(N>=2 / c).
// For integer N the two counts sum to N; for real N < 2 the law is the
// mixture of the neighbouring integer laws (003 Fig. 4), so they need not.
// `integer_gaussian` rounds the Gaussian part so that integer N gives integer
// counts (the multinomial needs this for its counts to sum to N exactly).
// (binomial_dual_gated_law below, with the conditional form of Law 6b.)

// The interior case of b(n, p) exactly: the k in [1, n - 1] with
// P(k | 1 <= k <= n - 1) = C(n, k) p^k (1 - p)^(n - k) / z, by inverting its CDF
// with xi from k = 1 upwards on the side of the smaller probability q =
// min(p, 1 - p) (pmf(k + 1) = pmf(k) (n - k) / (k + 1) q / (1 - q), from
// pmf(1) = n q (1 - q)^(n - 1)); pow_q = (1 - q)^n as the gates computed it.
// Integer n >= 2. At most 64 steps: callers use it where n q <= 16,
// where P(k > 64) < 1e-14.
float binomial_interior_inverse(float n, float p, float pow_pos, float pow_neg, float z, float xi) {
    bool mirror = p > 0.5f;
    float q = mirror ? 1.0f - p : p;
    float pow_q = mirror ? pow_pos : pow_neg;  // (1 - q)^n
    float pmf = n * q * pow_q / max(1.0f - q, 1e-30f);
    float ratio = q / max(1.0f - q, 1e-30f);
    float target = xi * z;
    float cdf = 0.0f;
    float k = 1.0f;
    for (int i = 0; i < 64; ++i) {
        cdf += pmf;
        if (cdf >= target || k >= n - 1.0f) break;
        pmf *= (n - k) / (k + 1.0f) * ratio;
        k += 1.0f;
    }
    return mirror ? n - k : k;
}

// Above this many trials n^2 overflows fp32 (n^2 > 3.4e38 at n > 1.8e19):
// the interior moments below then take their factored form.
const float BINOMIAL_MAX_SQUARED_TRIALS = 1e18f;

// The moments of the interior case of b(n, p) (see
// Law 6b below) for n > BINOMIAL_MAX_SQUARED_TRIALS, where the expanded
// E[n^2] - E[n]^2 overflows (inf - inf = NaN from log density ~44 on). With
// A = p^n, B = (1 - p)^n and z = 1 - A - B:
//   E   = n (p - A) / z,
//   Var = n p (1 - p) / z + (nA nB - nA n(1 - p)^2 - np np B) / z^2,
// each product ordered so that a factor that underflows to 0 (A or B, for
// any n here) multiplies before the other grows: every term is finite.
// Where z < 1e-6 (n p or n (1 - p) tiny; the Gaussian case then has
// probability z) the deviate is the mean: its variance is returned as 0
// (mean + 0 z is the mean exactly). Returns (mean, variance).
vec2 binomial_interior_moments_large(float n, float p, float pow_pos, float pow_neg, float z) {
    float mean = clamp(n * (p - pow_pos) / z, 1.0f, n - 1.0f);
    if (!(z >= 1e-6f)) return vec2(mean, 0.0f);
    float na = n * pow_pos;
    float nb = n * pow_neg;
    float np = n * p;
    float nq2 = n * (1.0f - p) * (1.0f - p);
    float variance = np * (1.0f - p) / z + (na * nb - na * nq2 - np * (np * pow_neg)) / (z * z);
    return vec2(mean, min(max(variance, 0.0f), 1e36f));
}

// Law 6b (an extension, not in 003; used by kneiphof2025's "conditional"
// option): Algorithm 1's gates with its Gaussian case drawn from b(N, p)
// conditioned on the interior 1 <= n <= N - 1, instead of Algorithm 1's
// Gaussian of mean 1 + (N - 2) p and variance (N - 2) p (1 - p) ("one known
// positive and one known negative, N - 2 free"), which overestimates E[b] by
// up to ~20 % where N p ~ 1-10 (e.g. N = 10, p = 0.1: +21 %).
//  - Integer N with N min(p, 1 - p) <= 16 (and integer_gaussian): the
//    interior law exactly, by inversion (binomial_interior_inverse): the law
//    is then b(N, p) exactly. A Gaussian with the interior moments, rounded
//    and clamped to [1, N - 1], was 4-6 % high at N p ~ 0.3-2 (the clamp
//    at 1 of a distribution piled up there) and is kept only for the case below.
//  - Otherwise a Gaussian with the interior case's moments, with
//    Z = 1 - p^N - (1 - p)^N (the gate of the Gaussian case, lines 5-6):
//      E[n | interior] = (N p - N p^N) / Z,
//      E[n^2 | interior] = (N p (1 - p) + N^2 p^2 - N^2 p^N) / Z;
//    residual bias < 0.1 % for N min(p, 1 - p) > 16
//    (Kneiphof2025.ConditionalLawIsUnbiased).
// Gating is unchanged. Non-integer N keeps Algorithm 1's interpolated gates;
// kneiphof2025 rounds N stochastically first (kneiphof2025.glsl).
//
// Both laws in one function (Law 6 where !conditional, Law 6b where
// conditional): the gates are the same, and the Gaussian's mean and
// variance are chosen before the one normal quantile the Gaussian needs
// (SIMD back ends such as llvmpipe run every side of a branch for a block
// of pixels, so callers that chose between two laws, and the laws' own
// cases, would pay for every quantile and power of each). The
// operations on the values are those of each law as written, so the counts
// are the same bit for bit (DualGatedLaw.BothLawsAsWritten, laws_as_written_test.cpp).
vec2 binomial_dual_gated_law(float N, float p, float xi1, float xi2, bool integer_gaussian,
                             bool conditional) {
    float n = max(N, 0.0f);
    float n2 = max(2.0f, n);                                   // line 2
    float c = stable_pow_scale(p);                             // line 3
    float w_many = clamp(n - 1.0f, 0.0f, 1.0f);
    float pow_pos = pow_unit(p, n2);
    float pow_neg = pow_unit(max(1.0f - c * p, 0.0f), n2 / c);
    float p_all_pos = w_many * pow_pos;                        // line 5
    float p_all_neg = w_many * pow_neg;                        // line 6
    float w_one = max(0.0f, 1.0f - abs(1.0f - n));
    float p_one_pos = w_one * p;                               // line 7
    float p_one_neg = w_one * (1.0f - p);                      // line 8
    float b_all_pos = xi1 < p_all_pos ? 1.0f : 0.0f;           // line 10
    float b_pos = xi1 < p_all_pos + p_one_pos ? 1.0f : 0.0f;   // line 11
    float b_all_neg = 1.0f - p_all_neg <= xi1 ? 1.0f : 0.0f;   // line 12
    float b_neg = 1.0f - p_all_neg - p_one_neg <= xi1 ? 1.0f : 0.0f;  // line 13
    float b_gauss = (n > 1.0f ? 1.0f : 0.0f) * (1.0f - b_pos) * (1.0f - b_neg);  // line 14
    float z = max(1.0f - pow_pos - pow_neg, 1e-30f);
    float g;
    if (conditional && integer_gaussian && n == floor(n) && n2 * min(p, 1.0f - p) <= 16.0f) {
        g = b_gauss > 0.0f ? binomial_interior_inverse(n2, p, pow_pos, pow_neg, z, xi2) : 1.0f;
    } else {
        // Algorithm 1 (lines 16-17): one known positive and one known negative, N - 2 free.
        float mean = 1.0f + (n2 - 2.0f) * p;
        float variance = (n2 - 2.0f) * p * (1.0f - p);
        if (conditional && n2 <= BINOMIAL_MAX_SQUARED_TRIALS) {
            float m = (n2 * p - n2 * pow_pos) / z;
            float second = (n2 * p * (1.0f - p) + n2 * n2 * p * p - n2 * n2 * pow_pos) / z;
            mean = clamp(m, 1.0f, n2 - 1.0f);
            variance = max(second - mean * mean, 0.0f);
        } else if (conditional) {
            vec2 moments = binomial_interior_moments_large(n2, p, pow_pos, pow_neg, z);
            mean = moments.x;
            variance = moments.y;
        }
        g = gaussian_from_standard(mean, variance, normal_quantile(xi2));
        if (integer_gaussian) g = floor(g + 0.5f);
    }
    g = clamp(g, 1.0f, n2 - 1.0f);                             // line 18
    float g_bar = n2 - g;                                      // line 19
    return vec2(b_all_pos * (n2 - 1.0f) + b_pos + b_gauss * g,            // line 21
                b_all_neg * (n2 - 1.0f) + b_neg + b_gauss * g_bar);       // line 22
}
vec2 binomial_dual_gated(float N, float p, float xi1, float xi2, bool integer_gaussian) {
    return binomial_dual_gated_law(N, p, xi1, xi2, integer_gaussian, false);
}
vec2 binomial_dual_gated_conditional(float N, float p, float xi1, float xi2, bool integer_gaussian) {
    return binomial_dual_gated_law(N, p, xi1, xi2, integer_gaussian, true);
}

#endif
