// The gated laws of counting/binomial_laws.glsl evaluate each law and its
// conditional form in one function (one normal quantile, one gate power):
// binomial_dual_gated_law (Algorithm 1 of Kneiphof & Klein 2025, 003, and
// Law 6b) and binomial_single_gated_law_of (003 Eq. 23 and Law 5b). These
// tests check that the results are, bit for bit, those of the laws written
// as separate functions (the references below, verbatim apart from their
// names), over N from below one
// trial to past the n^2 overflow bound, p from 1e-12 to 1.
#include <gtest/gtest.h>

#include <cmath>

#include "glintlab/core/glsl.h"
#include "glintlab/core/rng.h"

GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/counting/binomial_laws.glsl"

// The laws as separate functions.
SingleGatedLaw single_gated_law_as_written(float N, float p) {
    float n = max(N, 0.0f);
    float rest = max(n - 1.0f, 0.0f);
    SingleGatedLaw law;
    law.p_gate = min(n * p, 1.0f - pow_one_minus_stable(p, n));
    law.mean = 1.0f + rest * p;
    law.sd = sqrt(max(rest * p * (1.0f - p), 0.0f));
    law.top = max(n, 1.0f);
    law.scale = 1.0f;
    return law;
}

SingleGatedLaw single_gated_conditional_law_as_written(float N, float p) {
    float n = max(N, 0.0f);
    float np = n * p;
    SingleGatedLaw law;
    law.p_gate = min(np, 1.0f - pow_one_minus_stable(p, n));
    law.top = max(n, 1.0f);
    if (!(law.p_gate > 0.0f)) {
        law.mean = 1.0f;
        law.sd = 0.0f;
        law.scale = 1.0f;
        return law;
    }
    float mu = clamp(np / law.p_gate, 1.0f, law.top);
    law.mean = mu;
    law.sd = sqrt(max(mu * ((1.0f - p) - (mu - np)), 0.0f));
    law.scale = mu / clamped_gaussian_mean(mu, law.sd, 1.0f, law.top);
    return law;
}

vec2 dual_gated_as_written(float N, float p, float xi1, float xi2, bool integer_gaussian) {
    float n = max(N, 0.0f);
    float n2 = max(2.0f, n);
    float c = stable_pow_scale(p);
    float w_many = clamp(n - 1.0f, 0.0f, 1.0f);
    float p_all_pos = w_many * pow_unit(p, n2);
    float p_all_neg = w_many * pow_unit(max(1.0f - c * p, 0.0f), n2 / c);
    float w_one = max(0.0f, 1.0f - abs(1.0f - n));
    float p_one_pos = w_one * p;
    float p_one_neg = w_one * (1.0f - p);
    float b_all_pos = xi1 < p_all_pos ? 1.0f : 0.0f;
    float b_pos = xi1 < p_all_pos + p_one_pos ? 1.0f : 0.0f;
    float b_all_neg = 1.0f - p_all_neg <= xi1 ? 1.0f : 0.0f;
    float b_neg = 1.0f - p_all_neg - p_one_neg <= xi1 ? 1.0f : 0.0f;
    float b_gauss = (n > 1.0f ? 1.0f : 0.0f) * (1.0f - b_pos) * (1.0f - b_neg);
    float mean = 1.0f + (n2 - 2.0f) * p;
    float variance = (n2 - 2.0f) * p * (1.0f - p);
    float g = gaussian_deviate(mean, variance, xi2);
    if (integer_gaussian) g = floor(g + 0.5f);
    g = clamp(g, 1.0f, n2 - 1.0f);
    float g_bar = n2 - g;
    return vec2(b_all_pos * (n2 - 1.0f) + b_pos + b_gauss * g,
                b_all_neg * (n2 - 1.0f) + b_neg + b_gauss * g_bar);
}

float interior_gaussian_large_as_written(float n, float p, float pow_pos, float pow_neg, float z,
                                         float xi) {
    float mean = clamp(n * (p - pow_pos) / z, 1.0f, n - 1.0f);
    if (!(z >= 1e-6f)) return mean;
    float na = n * pow_pos;
    float nb = n * pow_neg;
    float np = n * p;
    float nq2 = n * (1.0f - p) * (1.0f - p);
    float variance = np * (1.0f - p) / z + (na * nb - na * nq2 - np * (np * pow_neg)) / (z * z);
    return gaussian_deviate(mean, min(max(variance, 0.0f), 1e36f), xi);
}

vec2 dual_gated_conditional_as_written(float N, float p, float xi1, float xi2,
                                       bool integer_gaussian) {
    float n = max(N, 0.0f);
    float n2 = max(2.0f, n);
    float c = stable_pow_scale(p);
    float w_many = clamp(n - 1.0f, 0.0f, 1.0f);
    float pow_pos = pow_unit(p, n2);
    float pow_neg = pow_unit(max(1.0f - c * p, 0.0f), n2 / c);
    float p_all_pos = w_many * pow_pos;
    float p_all_neg = w_many * pow_neg;
    float w_one = max(0.0f, 1.0f - abs(1.0f - n));
    float p_one_pos = w_one * p;
    float p_one_neg = w_one * (1.0f - p);
    float b_all_pos = xi1 < p_all_pos ? 1.0f : 0.0f;
    float b_pos = xi1 < p_all_pos + p_one_pos ? 1.0f : 0.0f;
    float b_all_neg = 1.0f - p_all_neg <= xi1 ? 1.0f : 0.0f;
    float b_neg = 1.0f - p_all_neg - p_one_neg <= xi1 ? 1.0f : 0.0f;
    float b_gauss = (n > 1.0f ? 1.0f : 0.0f) * (1.0f - b_pos) * (1.0f - b_neg);
    float z = max(1.0f - pow_pos - pow_neg, 1e-30f);
    float g;
    if (integer_gaussian && n == floor(n) && n2 * min(p, 1.0f - p) <= 16.0f) {
        g = b_gauss > 0.0f ? binomial_interior_inverse(n2, p, pow_pos, pow_neg, z, xi2) : 1.0f;
    } else if (n2 <= BINOMIAL_MAX_SQUARED_TRIALS) {
        float mean = (n2 * p - n2 * pow_pos) / z;
        float second = (n2 * p * (1.0f - p) + n2 * n2 * p * p - n2 * n2 * pow_pos) / z;
        mean = clamp(mean, 1.0f, n2 - 1.0f);
        float variance = max(second - mean * mean, 0.0f);
        g = gaussian_deviate(mean, variance, xi2);
        if (integer_gaussian) g = floor(g + 0.5f);
    } else {
        g = interior_gaussian_large_as_written(n2, p, pow_pos, pow_neg, z, xi2);
        if (integer_gaussian) g = floor(g + 0.5f);
    }
    g = clamp(g, 1.0f, n2 - 1.0f);
    float g_bar = n2 - g;
    return vec2(b_all_pos * (n2 - 1.0f) + b_pos + b_gauss * g,
                b_all_neg * (n2 - 1.0f) + b_neg + b_gauss * g_bar);
}
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

using namespace shader;

TEST(DualGatedLaw, BothLawsAsWritten) {
    Pcg32 rng(23, 7);
    int gaussian_cases = 0, inverse_cases = 0, large_cases = 0;
    for (int k = 0; k < 200000; ++k) {
        // log10 N in [-1, 21]: N < 1 (interpolated gates), integers (the
        // conditional law's exact inverse below N min(p, 1 - p) = 16),
        // and beyond BINOMIAL_MAX_SQUARED_TRIALS = 1e18.
        float N = std::pow(10.0f, -1.0f + 22.0f * rng.next_float());
        if (rng.next_uint(2) == 0) N = std::floor(N);
        const float p = rng.next_uint(8) == 0 ? 1.0f - std::pow(10.0f, -6.0f * rng.next_float())
                                              : std::pow(10.0f, -12.0f * rng.next_float());
        const float xi1 = rng.next_float(), xi2 = rng.next_float();
        const bool integer_gaussian = rng.next_uint(2) == 0;
        const glm::vec2 published = dual_gated_as_written(N, p, xi1, xi2, integer_gaussian);
        const glm::vec2 conditional =
            dual_gated_conditional_as_written(N, p, xi1, xi2, integer_gaussian);
        const glm::vec2 a = binomial_dual_gated_law(N, p, xi1, xi2, integer_gaussian, false);
        const glm::vec2 b = binomial_dual_gated_law(N, p, xi1, xi2, integer_gaussian, true);
        ASSERT_EQ(a.x, published.x) << "N " << N << " p " << p << " xi " << xi1 << " " << xi2;
        ASSERT_EQ(a.y, published.y) << "N " << N << " p " << p;
        ASSERT_EQ(b.x, conditional.x) << "N " << N << " p " << p << " xi " << xi1 << " " << xi2;
        ASSERT_EQ(b.y, conditional.y) << "N " << N << " p " << p;
        const float n2 = std::max(2.0f, N);
        const bool gauss = N > 1.0f && b.x > 0.0f && b.y > 0.0f;  // the interior case drawn
        const bool inverse =
            integer_gaussian && N == std::floor(N) && n2 * std::min(p, 1.0f - p) <= 16.0f;
        gaussian_cases += gauss && !inverse;
        inverse_cases += gauss && inverse;
        large_cases += gauss && n2 > BINOMIAL_MAX_SQUARED_TRIALS;
    }
    // Every branch of the conditional law was compared on drawn counts.
    EXPECT_GE(gaussian_cases, 10000);
    EXPECT_GE(inverse_cases, 1000);
    EXPECT_GE(large_cases, 1000);
}

TEST(DualGatedLaw, LargeNMeanOnlyCaseAsWritten) {
    // Past 1e18 trials with N p ~ 1e-7..1e-5, the interior case has
    // probability Z < 1e-6 and the conditional law draws its mean only; a
    // small gate uniform xi1 < Z lands in that case.
    Pcg32 rng(29, 1);
    int mean_only = 0;
    for (int k = 0; k < 20000; ++k) {
        const float N = std::pow(10.0f, 18.5f + 2.5f * rng.next_float());
        const float p = std::pow(10.0f, -7.0f + 2.0f * rng.next_float()) / N;
        const float xi1 = 1e-9f * rng.next_float(), xi2 = rng.next_float();
        const bool integer_gaussian = rng.next_uint(2) == 0;
        const glm::vec2 expected =
            dual_gated_conditional_as_written(N, p, xi1, xi2, integer_gaussian);
        const glm::vec2 got = binomial_dual_gated_law(N, p, xi1, xi2, integer_gaussian, true);
        ASSERT_EQ(got.x, expected.x) << "N " << N << " p " << p;
        ASSERT_EQ(got.y, expected.y) << "N " << N << " p " << p;
        mean_only += expected.x > 0.0f && expected.y > 0.0f;
    }
    EXPECT_GE(mean_only, 1000);
}

TEST(SingleGatedLaw, BothFormsAsWritten) {
    Pcg32 rng(31, 5);
    int conditional_cases = 0;
    for (int k = 0; k < 200000; ++k) {
        const float N = k % 97 == 0 ? 0.0f : std::pow(10.0f, -3.0f + 24.0f * rng.next_float());
        const float p = k % 89 == 0 ? 0.0f : std::pow(10.0f, -12.0f * rng.next_float());
        const SingleGatedLaw a = single_gated_law_as_written(N, p);
        const SingleGatedLaw b = single_gated_conditional_law_as_written(N, p);
        const SingleGatedLaw a2 = binomial_single_gated_law_of(N, p, false);
        const SingleGatedLaw b2 = binomial_single_gated_law_of(N, p, true);
        for (const auto& [got, want] : {std::pair{a2, a}, std::pair{b2, b}}) {
            ASSERT_EQ(got.p_gate, want.p_gate) << "N " << N << " p " << p;
            ASSERT_EQ(got.mean, want.mean) << "N " << N << " p " << p;
            ASSERT_EQ(got.sd, want.sd) << "N " << N << " p " << p;
            ASSERT_EQ(got.top, want.top) << "N " << N << " p " << p;
            ASSERT_EQ(got.scale, want.scale) << "N " << N << " p " << p;
        }
        conditional_cases += b.scale != 1.0f;
    }
    // The conditional form's mean correction was compared where it acts.
    EXPECT_GE(conditional_cases, 10000);
}

}  // namespace
}  // namespace glintlab
