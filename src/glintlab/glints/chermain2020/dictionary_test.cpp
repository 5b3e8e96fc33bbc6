#include "glintlab/glints/chermain2020/dictionary.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

// Integral over R of the even, piecewise-linear marginal (zero at slope_max).
double marginal_integral(const Dictionary& d, int dist, int level) {
    const double dx = d.slope_max / d.params.table_size;
    double sum = 0.0;
    for (int k = 0; k < d.params.table_size; ++k) sum += d.at(dist, level, k);
    return 2.0 * dx * (sum - 0.5 * d.at(dist, level, 0));
}

TEST(Chermain2020Dictionary, DeterministicAndNormalised) {
    DictionaryParams p;
    p.n_levels = 10;
    p.n_dists = 8;
    const Dictionary a = generate_dictionary(p), b = generate_dictionary(p);
    EXPECT_EQ(a.values, b.values);
    for (int i = 0; i < p.n_dists; ++i)
        for (int l = 0; l < p.n_levels; ++l) {
            // Eq. 4 (normalisation) of each marginal: fp32 rounding of 64 values only.
            EXPECT_NEAR(marginal_integral(a, i, l), 1.0, 1e-5) << i << " " << l;
            for (int k = 0; k < p.table_size; ++k) ASSERT_GE(a.at(i, l, k), 0.0f);
        }
    p.seed += 1;
    EXPECT_NE(generate_dictionary(p).values, a.values);
}

TEST(Chermain2020Dictionary, LevelZeroIsOneMirroredLobe) {
    // 004 §4.3 "finest LOD": one draw, two lobes at +-mu. The marginal has at
    // most two local maxima on x >= 0 (one at mu, or one at 0 if mu < lobe sigma).
    const Dictionary& d = default_dictionary();
    for (int i = 0; i < d.params.n_dists; ++i) {
        int maxima = 0;
        for (int k = 1; k + 1 < d.params.table_size; ++k)
            if (d.at(i, 0, k) > d.at(i, 0, k - 1) && d.at(i, 0, k) >= d.at(i, 0, k + 1)) ++maxima;
        EXPECT_LE(maxima, 1) << i;
    }
}

TEST(Chermain2020Dictionary, FinestLevelMeanIsTheBeckmannMarginal) {
    // Mean over the 192 marginals of level 15: a kernel estimate from
    // 192 * 2^15 = 6.3e6 draws of N(0, sigma), sigma = alpha/sqrt(2) = 0.354,
    // with kernel std-dev 0.02. Kernel bias: density of N(0, sigma^2 + 0.02^2),
    // < 0.4 % for |x| < 2 sigma; sampling noise < 0.1 % (>= 1.5e5 draws per
    // kernel width there). Tolerance 1 % over |x| < 2 sigma.
    const Dictionary& d = default_dictionary();
    const DictionaryParams& p = d.params;
    const double alpha = p.alpha_dict;
    const int top = p.n_levels - 1;
    for (int k = 0; k < p.table_size / 2; ++k) {
        double mean = 0.0;
        for (int i = 0; i < p.n_dists; ++i) mean += d.at(i, top, k);
        mean /= p.n_dists;
        const double x = k * double(d.slope_max) / p.table_size;
        const double target = std::exp(-x * x / (alpha * alpha)) / (std::sqrt(M_PI) * alpha);
        EXPECT_NEAR(mean / target, 1.0, 0.01) << "x = " << x;
    }
}

TEST(Chermain2020Dictionary, RejectsParametersOutOfRange) {
    DictionaryParams p;
    p.n_levels = 0;
    EXPECT_THROW(check_dictionary_params(p), Error);
    p = {};
    p.lobe_sigma = 0.3f;  // > alpha_dict / 2
    EXPECT_THROW(check_dictionary_params(p), Error);
    p = {};
    p.table_size = 2;
    EXPECT_THROW(check_dictionary_params(p), Error);
    EXPECT_NO_THROW(check_dictionary_params(DictionaryParams{}));
}

}  // namespace
}  // namespace glintlab
