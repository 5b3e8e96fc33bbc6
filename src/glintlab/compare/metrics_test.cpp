#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "glintlab/compare/metrics.h"
#include "glintlab/core/error.h"

namespace glintlab::compare {
namespace {

// A plane of deterministic pseudo-random values in [lo, hi).
Plane noise(int w, int h, uint64_t seed, float lo = 0.0f, float hi = 1.0f) {
    Plane p(w, h);
    uint64_t s = seed * 0x9E3779B97F4A7C15ull + 1;
    for (float& v : p.values) {
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;  // xorshift64
        v = lo + (hi - lo) * float(double(s >> 11) / double(1ull << 53));
    }
    return p;
}

Mask all(const Plane& p) {
    return Mask(p.values.size(), 1);
}

TEST(CompareMetrics, IdenticalImagesHaveNoError) {
    const Plane a = noise(16, 12, 1);
    const Plane b = noise(16, 12, 2);
    const Mask m = all(a);
    EXPECT_EQ(blurred_relative_rmse(a, a, m, 2.0), 0.0);
    EXPECT_EQ(wasserstein1(a.values, a.values), 0.0);
    // A model equal to the truth realization by realization: ratio 1; equal
    // realizations: no variance. Of two values the sample variance is
    // (a - b)^2 / 2.
    const std::vector<Plane> r = {a, b};
    double expected = 0.0;
    for (size_t i = 0; i < a.values.size(); ++i)
        expected += 0.5 * double(a.values[i] - b.values[i]) * double(a.values[i] - b.values[i]);
    expected /= double(a.values.size());
    EXPECT_NEAR(mean_pixel_variance(r, m), expected, 1e-6);
    EXPECT_EQ(mean_pixel_variance({a, a}, m), 0.0);
    EXPECT_THROW(mean_pixel_variance({a}, m), Error);
    const MeanError e = mean_relative_error({0.5, 0.7}, {0.5, 0.7});
    EXPECT_EQ(e.relative_error, 0.0);
    // Two realizations each of spread 0.2: sample variance 0.02 each, so
    // se = sqrt(0.02/2 + 0.02/2) / 0.6.
    EXPECT_NEAR(e.standard_error, std::sqrt(0.02) / 0.6, 1e-12);
}

// A model image that is the truth scaled by s: relative error s - 1 exactly
// (every statistic is linear in the image), and the blurred RMSE |s - 1| times
// the RMS of the blurred truth over its mean.
TEST(CompareMetrics, ScaledImageGivesTheExactRelativeError) {
    const Plane g = noise(20, 20, 3, 0.5f, 1.5f);
    Plane m = g;
    for (float& v : m.values) v *= 1.25f;
    const Mask mask = all(g);
    const MeanError e = mean_relative_error({masked_mean(m, mask)}, {masked_mean(g, mask)});
    EXPECT_NEAR(e.relative_error, 0.25, 1e-6);  // float sums: 1e-6 relative
    EXPECT_EQ(e.standard_error, 0.0);           // one realization: no spread
    const Plane bg = gaussian_blur(g, 1.5);
    double sq = 0.0, mean = 0.0;
    for (float v : bg.values) sq += double(v) * v, mean += v;
    sq /= double(bg.values.size()), mean /= double(bg.values.size());
    EXPECT_NEAR(blurred_relative_rmse(m, g, mask, 1.5), 0.25 * std::sqrt(sq) / mean, 1e-5);
    // Variance scales by s^2, so the ratio of a scaled pair is 1.5625.
    const Plane g2 = noise(20, 20, 4, 0.5f, 1.5f);
    Plane m2 = g2;
    for (float& v : m2.values) v *= 1.25f;
    EXPECT_NEAR(mean_pixel_variance({m, m2}, mask) / mean_pixel_variance({g, g2}, mask), 1.5625,
                1e-5);
}

// Realizations = structure + sampling noise, both uniform with variance
// 1/3 (width 2): mean_pixel_variance sees both (2/3), sampling_pixel_variance
// of a render and its resampled twin (same structure, other noise) only the
// noise (1/3), so their difference is the structure's 1/3. Over 64 x 64
// pixels the relative standard errors are 1.9 % for the sampling estimate
// (d = N - N' is triangular: E[d^2] = 2/3, E[d^4] = 16/15, so sd(d^2) /
// E[d^2] = 1.18, / sqrt(4096)) and 0.8 % for the total (sqrt(2 / (R - 1)) /
// 64 with R = 8): 6 % is more than 3 of them. The seeds are fixed, so the
// test is deterministic.
TEST(CompareMetrics, SamplingVarianceSeparatesNoiseFromStructure) {
    constexpr int kW = 64, kH = 64, kR = 8;
    auto add = [](Plane a, const Plane& b) {
        for (size_t i = 0; i < a.values.size(); ++i) a.values[i] += b.values[i];
        return a;
    };
    std::vector<Plane> renders;
    for (int r = 0; r < kR; ++r)
        renders.push_back(
            add(noise(kW, kH, 100 + r, 0.0f, 2.0f), noise(kW, kH, 200 + r, -1.0f, 1.0f)));
    const Plane twin = add(noise(kW, kH, 100, 0.0f, 2.0f), noise(kW, kH, 300, -1.0f, 1.0f));
    const Mask m = all(twin);
    const double total = mean_pixel_variance(renders, m);
    const double sampling = sampling_pixel_variance(renders[0], twin, m);
    EXPECT_NEAR(total, 2.0 / 3.0, 0.06 * 2.0 / 3.0);
    EXPECT_NEAR(sampling, 1.0 / 3.0, 0.06 / 3.0);
    EXPECT_NEAR(total - sampling, 1.0 / 3.0, 0.12 / 3.0);  // both errors add at worst
    // The same render twice: no sampling noise (a deterministic renderer).
    EXPECT_EQ(sampling_pixel_variance(renders[0], renders[0], m), 0.0);
    EXPECT_THROW(sampling_pixel_variance(renders[0], noise(8, 8, 1), m), Error);
}

TEST(CompareMetrics, MaskSelectsThePixels) {
    Plane p(4, 1);
    p.values = {1.0f, 100.0f, 3.0f, -50.0f};
    EXPECT_DOUBLE_EQ(masked_mean(p, Mask{1, 0, 1, 0}), 2.0);
    EXPECT_EQ(masked_mean(p, Mask{0, 0, 0, 0}), 0.0);
    EXPECT_THROW(masked_mean(p, Mask{1, 1}), Error);
}

// W1 of a sample and the same sample shifted by c is |c|; of {0} and {1, 3}
// it is the mean distance 2 (all mass of one point moves); of {0, 1} and
// {0, 3}: half the mass moves by 2, so 1.
TEST(CompareMetrics, WassersteinOfShiftedDistributions) {
    const Plane a = noise(32, 8, 5);
    std::vector<float> shifted = a.values;
    for (float& v : shifted) v += 0.375f;
    EXPECT_NEAR(wasserstein1(a.values, shifted), 0.375, 1e-6);
    EXPECT_NEAR(wasserstein1(shifted, a.values), 0.375, 1e-6);
    EXPECT_DOUBLE_EQ(wasserstein1({0.0f}, {1.0f, 3.0f}), 2.0);
    EXPECT_DOUBLE_EQ(wasserstein1({0.0f, 1.0f}, {0.0f, 3.0f}), 1.0);
    // Order does not matter; different sizes are allowed.
    EXPECT_DOUBLE_EQ(wasserstein1({3.0f, 0.0f}, {1.0f, 0.0f}), 1.0);
    EXPECT_NEAR(wasserstein1({0.0f, 0.0f, 1.0f}, {0.0f, 1.0f}), 1.0 / 6.0, 1e-12);
    EXPECT_THROW(wasserstein1({}, {1.0f}), Error);
}

TEST(CompareMetrics, GaussianBlurKeepsConstantsAndMass) {
    const Plane c(9, 7, 2.5f);
    for (float v : gaussian_blur(c, 1.7).values) EXPECT_NEAR(v, 2.5f, 1e-5);
    // A point well inside: the blurred plane sums to the point's value.
    Plane d(41, 41);
    d.values[20 * 41 + 20] = 1.0f;
    double sum = 0.0;
    const Plane b = gaussian_blur(d, 2.0);
    for (float v : b.values) sum += v;
    EXPECT_NEAR(sum, 1.0, 1e-5);
    EXPECT_GT(b.values[20 * 41 + 20], b.values[20 * 41 + 22]);
    EXPECT_EQ(sparkle_blur_sigma(64, 64), 2.0);
    EXPECT_EQ(sparkle_blur_sigma(32, 16), 1.5);
}

// A frozen sequence has no flicker; two frames alternating between a and 2a
// change by a per pixel against a mean level of 1.5a: 2/3.
TEST(CompareMetrics, FlickerOfKnownSequences) {
    const Plane a = noise(10, 10, 6, 0.5f, 1.0f);
    const Mask m = all(a);
    EXPECT_EQ(flicker({a, a, a}, {m, m, m}), 0.0);
    Plane b = a;
    for (float& v : b.values) v *= 2.0f;
    EXPECT_NEAR(flicker({a, b, a}, {m, m, m}), 2.0 / 3.0, 1e-6);
    EXPECT_THROW(flicker({a}, {m}), Error);
}

// Over several paths the flicker is the mean of the paths' flicker values
// and its standard error their sample sd / sqrt(paths): a frozen path (0)
// and an alternating one (2/3) give 1/3 +- (2/3) / sqrt(2) / sqrt(2) = 1/3;
// one path has the path's value and no standard error.
TEST(CompareMetrics, FlickerOverPathsIsTheMeanWithItsStandardError) {
    const Plane a = noise(10, 10, 6, 0.5f, 1.0f);
    const Mask m = all(a);
    Plane b = a;
    for (float& v : b.values) v *= 2.0f;
    const FlickerEstimate one = flicker_over_paths({{a, b, a}}, {m, m, m});
    EXPECT_NEAR(one.mean, 2.0 / 3.0, 1e-6);
    EXPECT_EQ(one.standard_error, 0.0);
    const FlickerEstimate two = flicker_over_paths({{a, a, a}, {a, b, a}}, {m, m, m});
    EXPECT_NEAR(two.mean, 1.0 / 3.0, 1e-6);
    EXPECT_NEAR(two.standard_error, 1.0 / 3.0, 1e-6);
    EXPECT_THROW(flicker_over_paths({}, {m, m, m}), Error);
}

// The sample statistics every estimate of the compare tool uses: n - 1 in
// the variance, sd / sqrt(n) for the standard error, nothing for one value.
TEST(CompareMetrics, SampleMeanVarianceAndStandardError) {
    EXPECT_EQ(sample_mean_variance({}), (std::pair<double, double>{0.0, 0.0}));
    EXPECT_EQ(sample_mean_variance({5.0}), (std::pair<double, double>{5.0, 0.0}));
    const auto [m, v] = sample_mean_variance({1.0, 2.0, 3.0, 6.0});
    EXPECT_DOUBLE_EQ(m, 3.0);
    EXPECT_DOUBLE_EQ(v, 14.0 / 3.0);
    const MeanEstimate e = mean_with_standard_error({1.0, 2.0, 3.0, 6.0});
    EXPECT_DOUBLE_EQ(e.mean, 3.0);
    EXPECT_DOUBLE_EQ(e.standard_error, std::sqrt(14.0 / 3.0 / 4.0));
    EXPECT_EQ(mean_with_standard_error({5.0}).standard_error, 0.0);
}

TEST(CompareMetrics, CountsFaultyPixels) {
    Image img(3, 2, glm::vec3(0.5f));
    img.at(0, 0) = glm::vec3(std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f);
    img.at(1, 0) = glm::vec3(0.0f, std::numeric_limits<float>::infinity(), 0.0f);
    img.at(2, 0) = glm::vec3(0.0f, 0.0f, -1e-6f);
    img.at(0, 1) = glm::vec3(-1.0f, -1.0f, -1.0f);
    const PixelFaults f = count_pixel_faults(img);
    EXPECT_EQ(f.nan, 1);
    EXPECT_EQ(f.inf, 1);
    EXPECT_EQ(f.negative, 2);
    // Non-finite pixels do not poison the luminance statistics.
    const Plane l = luminance_plane(img);
    EXPECT_EQ(l.values[0], 0.0f);
    EXPECT_EQ(l.values[1], 0.0f);
    EXPECT_TRUE(std::isfinite(masked_mean(l, Mask(6, 1))));
}

TEST(CompareMetrics, MeanErrorOfABlackTruth) {
    EXPECT_EQ(mean_relative_error({0.0, 0.0}, {0.0, 0.0}).relative_error, 0.0);
    EXPECT_TRUE(std::isinf(mean_relative_error({1.0}, {0.0}).relative_error));
    EXPECT_THROW(mean_relative_error({}, {1.0}), Error);
}

}  // namespace
}  // namespace glintlab::compare
