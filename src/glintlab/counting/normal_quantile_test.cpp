#include <gtest/gtest.h>

#include <cmath>

#include <boost/math/distributions/normal.hpp>

#include "glintlab/counting/laws.h"

namespace glintlab {
namespace {

// Giles' single-precision erfinv is accurate to a few fp32 ulps of |z| <= 5.3
// (~1e-6 absolute); 1e-5 leaves a margin of 10 over that and is far below what
// a wrong coefficient or fp32 cancellation gives (3e-4 for Acklam's form).
TEST(CountingNormalQuantile, MatchesBoostOverTheUnitInterval) {
    const boost::math::normal_distribution<double> normal;
    double worst = 0.0;
    for (int i = 1; i < 200000; ++i) {
        const float u = static_cast<float>(i) / 200000.0f;
        const double truth = boost::math::quantile(normal, static_cast<double>(u));
        worst = std::max(worst, std::abs(shader::normal_quantile(u) - truth));
    }
    // Deep tails: u = 2^-k, where the tail branch works.
    for (int k = 7; k <= 24; ++k) {
        const float u = std::ldexp(1.0f, -k);
        const double truth = boost::math::quantile(normal, static_cast<double>(u));
        worst = std::max(worst, std::abs(shader::normal_quantile(u) - truth));
        worst = std::max(worst, std::abs(shader::normal_quantile(1.0f - u) + truth));
    }
    EXPECT_LT(worst, 1e-5);
}

TEST(CountingNormalQuantile, FiniteAtTheEnds) {
    EXPECT_TRUE(std::isfinite(shader::normal_quantile(0.0f)));
    EXPECT_TRUE(std::isfinite(shader::normal_quantile(1.0f)));
    EXPECT_LT(shader::normal_quantile(0.0f), -5.2f);
    EXPECT_GT(shader::normal_quantile(1.0f), 5.2f);
}

}  // namespace
}  // namespace glintlab
