// Regression tests of kneiphof2025 at the top of its documented ranges (log
// density up to 60, density_randomization up to 50): trial counts up to
// N = e^80 per vertex used to overflow fp32 in the conditional law's moments
// (n^2 > 3.4e38 from n ~ 1.8e19: inf - inf) and in the radiance-weighted
// counts (L N > 3.4e38), giving NaN pixels.
#include <gtest/gtest.h>

#include <cmath>

#include "glintlab/core/glsl.h"
#include "glintlab/core/rng.h"
#include "glintlab/validate/random_queries.h"

// Last: it compiles shader code (and its structs) into this file's own namespace.
#include "glintlab/glints/kneiphof2025/kneiphof2025_without_maps_test_util.h"

namespace glintlab {
namespace {

// The conditional law at n = 1e19 ... 5.5e34 (e^80): finite counts that sum
// to n (integer n: n2 - g + g), for p from 1e-38 to 1.
TEST(Kneiphof2025Overflow, ConditionalLawIsFiniteForHugeTrialCounts) {
    Pcg32 rng(3u, 5u);
    for (const float n : {1e18f, 2e19f, 1e25f, 5.5e34f}) {
        for (const float p : {0.0f, 1e-38f, 1e-20f, 1e-6f, 0.3f, 0.5f, 0.999f, 1.0f}) {
            for (int i = 0; i < 200; ++i) {
                const float xi1 = rng.next_float(), xi2 = rng.next_float();
                const glm::vec2 c = shader::binomial_dual_gated_conditional(n, p, xi1, xi2, true);
                ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y)) << n << " " << p;
                ASSERT_GE(c.x, 0.0f);
                ASSERT_GE(c.y, 0.0f);
                // Counts of n trials: their sum is n up to fp32 rounding of n - g (2^-23 relative).
                ASSERT_NEAR((double(c.x) + double(c.y)) / double(n), 1.0, 1e-6) << n << " " << p;
            }
        }
    }
}

// The moments stay right: at n = 1e20, p = 0.3 the Gaussian's mean is n p
// (relative standard deviation sqrt((1 - p) / (n p)) ~ 2e-10, far below fp32's
// 6e-8): the mean of 1000 draws is n p within 1e-6 (fp32 rounding).
TEST(Kneiphof2025Overflow, ConditionalLawMeanIsNpForHugeN) {
    Pcg32 rng(7u, 9u);
    const float n = 1e20f, p = 0.3f;
    double sum = 0.0;
    for (int i = 0; i < 1000; ++i)
        sum +=
            shader::binomial_dual_gated_conditional(n, p, rng.next_float(), rng.next_float(), true)
                .x;
    EXPECT_NEAR(sum / 1000.0 / (double(n) * p), 1.0, 1e-6);
}

// Eq. 17's glint factor under a bright environment (levels up to 3e7, a rare
// sun at p = 1e-3) at log density 44-60 and density_randomization up to 50:
// always finite and non-negative (it was NaN); without randomization and with
// N p of the rarest level >= 1e9 per footprint its counts concentrate
// (relative spread 1 / sqrt(N p) < 1e-4), so the factor is 1 within 1e-3.
TEST(Kneiphof2025Overflow, IblFactorIsFiniteAndTendsToOne) {
    const glm::vec4 p_a(0.5f, 0.3f, 0.199f, 1e-3f), L_a(0.0f, 1e3f, 1e6f, 3e7f);
    const glm::vec4 zero(0.0f);
    Pcg32 rng(21u, 4u);
    int near_one = 0;
    for (const float ld : {44.0f, 50.0f, 60.0f}) {
        for (const float randomization : {0.0f, 20.0f, 50.0f}) {
            for (const bool conditional : {true, false}) {
                for (int i = 0; i < 100; ++i) {
                    const double minor = pow10_uniform(rng, -4, -1);
                    const Footprint fp =
                        oriented_footprint(glm::vec2(rng.next_float(), rng.next_float()), minor,
                                           pow10_uniform(rng, 0, 2), rng.next_double() * 6.28);
                    const float f = shader::kneiphof2025_ibl_factor(fp, ld, rng.next_uint(), 1.0f,
                                                                    randomization, 4, p_a, zero,
                                                                    L_a, zero, conditional);
                    ASSERT_TRUE(std::isfinite(f) && f >= 0.0f)
                        << "ld " << ld << " randomization " << randomization << " f " << f;
                    if (randomization == 0.0f && ld >= 50.0f) {
                        EXPECT_NEAR(f, 1.0f, 1e-3f) << "ld " << ld << " minor " << minor;
                        ++near_one;
                    }
                }
            }
        }
    }
    EXPECT_EQ(near_one, 400);
}

// The scaled sums are bit for bit the plain ones below 2^64 trials (renders of
// ordinary scenes are unchanged) and rescale exactly by powers of two.
TEST(Kneiphof2025Overflow, ScaledSumsAreExactPowersOfTwo) {
    EXPECT_EQ(shader::kneiphof2025_count_exponent(1e19f), 0.0f);
    EXPECT_GT(shader::kneiphof2025_count_exponent(1e20f), 0.0f);
    glm::vec3 acc(0.0f);
    acc = shader::kneiphof2025_scaled_add(acc, glm::vec2(3.0f, 5.0f), 0.0f);
    EXPECT_EQ(acc, glm::vec3(3.0f, 5.0f, 0.0f));
    acc = shader::kneiphof2025_scaled_add(acc, glm::vec2(1.0f, 1.0f), 2.0f);
    EXPECT_EQ(acc, glm::vec3(0.75f + 1.0f, 1.25f + 1.0f, 2.0f));
    acc = shader::kneiphof2025_scaled_add(acc, glm::vec2(4.0f, 8.0f), 0.0f);
    EXPECT_EQ(acc, glm::vec3(2.75f, 4.25f, 2.0f));
}

}  // namespace
}  // namespace glintlab
