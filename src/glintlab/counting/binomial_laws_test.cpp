// Statistical and numerical properties of the shared counting laws.
// The grid statistics are computed once (20000 Latin-hypercube samples per
// cell, fixed seeds) and shared by the tests below.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include <tbb/parallel_for.h>

#include "glintlab/core/rng.h"
#include "glintlab/counting/cell_statistics.h"
#include "glintlab/counting/laws.h"
#include "glintlab/counting/pow_accuracy.h"
#include "glintlab/counting/robustness.h"

namespace glintlab {
namespace {

constexpr std::array<double, 13> kN = {0.3, 0.7, 1, 1.5, 2, 3, 5, 10, 30, 100, 1e3, 1e4, 1e6};
constexpr std::array<double, 7> kP = {1e-7, 1e-4, 1e-2, 0.1, 0.3, 0.5, 0.9};
constexpr int kSamples = 20000;

struct Grid {
    // stats[law][N index][p index]
    std::vector<std::vector<std::vector<CellStatistics>>> stats;
    const CellStatistics& at(CountingLaw law, size_t i, size_t j) const {
        return stats[static_cast<size_t>(law)][i][j];
    }
};

const Grid& grid() {
    static const Grid g = [] {
        Grid r;
        const auto laws = all_counting_laws();
        r.stats.assign(laws.size(), std::vector<std::vector<CellStatistics>>(
                                        kN.size(), std::vector<CellStatistics>(kP.size())));
        const size_t cells = kN.size() * kP.size();
        tbb::parallel_for(size_t{0}, cells, [&](size_t c) {
            const size_t i = c / kP.size(), j = c % kP.size();
            const BinomialReference ref(static_cast<float>(kN[i]), static_cast<float>(kP[j]));
            for (CountingLaw law : laws)
                r.stats[static_cast<size_t>(law)][i][j] =
                    measure_cell(law, ref, kSamples, 977u * c + static_cast<uint64_t>(law));
        });
        return r;
    }();
    return g;
}

// The laws' contract, mean within 1 % (or 1e-3 absolute) of N p, checked
// where the gated Gaussians' construction allows it (see in_mean_domain in
// validate_counting.cpp for the derivation): N p >= 200 (bias <= 1 count =
// 0.5 %), N >= 1 with N p <= 0.01 (bias ~ N p / 2 relative), and N < 1 for
// the 003 laws (exact by Eq. 23 / Appendix B). Noise: with Latin-hypercube
// gating the number of passed gates is n P +- 1, i.e. 5e-5 absolute, and the
// Gaussian part's mean error is below sigma / sqrt(n) (<= 0.05 % of N p when
// N p >= 200); the bias bounds keep at least half of the 1 % for it.
TEST(CountingLaws, GatedMeansWithinOnePercentInTheirAsymptoticRegimes) {
    int checked = 0;
    for (CountingLaw law : all_counting_laws()) {
        if (!is_gated(law)) continue;
        for (size_t i = 0; i < kN.size(); ++i) {
            for (size_t j = 0; j < kP.size(); ++j) {
                const double N = kN[i], p = kP[j], np = N * p;
                const bool exact_small_N =
                    N < 1.0 && law != CountingLaw::deliot2023;  // 003 Appendix B
                // (1 + 1e-9: N p = 100 x 1e-4 must not fall out by rounding.)
                if (!(np >= 200.0 || (N >= 1.0 && np <= 0.01 * (1.0 + 1e-9)) || exact_small_N))
                    continue;
                const CellStatistics& s = grid().at(law, i, j);
                EXPECT_LE(std::abs(s.mean - s.ref_mean), 0.01 * std::max(s.ref_mean, 0.1))
                    << law_name(law) << " N=" << N << " p=" << p << " mean=" << s.mean;
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 4 * 31 + 3 * 14);  // the domain is what the comment says
}

// 003 Fig. 12: the dual-gated law is closer to the binomial than the
// single-gated one at low N. On average over the N <= 10 cells, and cell by
// cell for N <= 2 where Algorithm 1 samples the (mixture) law exactly: its TV
// is then pure sampling noise, at most 0.5 sum_k sqrt(2 P_k / (pi n)) <= 0.009
// for 3 outcomes and n = 20000 (independent draws; Latin hypercube is lower).
TEST(CountingLaws, DualGatedCloserToBinomialThanSingleGatedForSmallN) {
    double dual = 0.0, single = 0.0;
    for (size_t i = 0; i < kN.size(); ++i) {
        if (kN[i] > 10.0) continue;
        for (size_t j = 0; j < kP.size(); ++j) {
            const double tv_dual = grid().at(CountingLaw::dual_gated, i, j).tv;
            const double tv_single = grid().at(CountingLaw::single_gated, i, j).tv;
            dual += tv_dual;
            single += tv_single;
            if (kN[i] <= 2.0) {
                EXPECT_LE(tv_dual, 0.01) << "N=" << kN[i] << " p=" << kP[j];
                EXPECT_LE(tv_dual, tv_single + 0.01) << "N=" << kN[i] << " p=" << kP[j];
            }
        }
    }
    EXPECT_LT(dual, single);
}

// The laws' contract, TV <= 0.02 for N >= 10 where the Gaussian regime applies,
// taken as N p (1 - p) >= 625 (sigma >= 25): each law is the binomial's
// Gaussian shifted by at most one count, which moves it by
// TV <= 1 / (sigma sqrt(2 pi)) <= 0.016, plus the binomial's own skewness error
// ~|1 - 2p| / (6 sigma) <= 0.007: together <= 0.5 / sigma = 0.02. Sampling
// noise of the estimate with ~5 bins per sigma and Latin-hypercube uniforms is
// ~0.003 (exact sampler: 1e-4).
TEST(CountingLaws, AllLawsCloseToBinomialInTheGaussianRegime) {
    int checked = 0;
    for (CountingLaw law : all_counting_laws()) {
        for (size_t i = 0; i < kN.size(); ++i) {
            for (size_t j = 0; j < kP.size(); ++j) {
                if (kN[i] < 10.0 || kN[i] * kP[j] * (1.0 - kP[j]) < 625.0) continue;
                EXPECT_LE(grid().at(law, i, j).tv, 0.02)
                    << law_name(law) << " N=" << kN[i] << " p=" << kP[j];
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 0);
}

TEST(CountingLaws, ExactSamplerMatchesItsOwnLaw) {
    // Inversion of the exact CDF: TV is sampling noise only (<= 0.01, as above).
    for (size_t i = 0; i < kN.size(); ++i)
        for (size_t j = 0; j < kP.size(); ++j)
            EXPECT_LE(grid().at(CountingLaw::exact, i, j).tv, 0.01);
}

TEST(CountingLaws, NoNanInfOrNegativeOutputOnTenMillionRandomInputs) {
    const RobustnessResult r = sweep_counting_laws(10'000'000, 12345u);
    EXPECT_EQ(r.invalid, 0);
    EXPECT_EQ(r.evaluations, 16 * 10'000'000LL);  // 12 law outputs + 4 multinomial bins
    // The named edges, explicitly.
    const float edges_N[] = {0.0f, 1.0f, 2.0f, 1e15f, 1e20f, 5.5e34f};
    const float edges_p[] = {0.0f, 1.0f, 1e-31f, 1e-45f, 0.5f};
    const float edges_xi[] = {0.0f, 0.5f, shader::ONE_MINUS_EPSILON};
    for (float N : edges_N) {
        for (float p : edges_p) {
            for (float xi : edges_xi) {
                const float v[] = {shader::binomial_gaussian(N, p, xi),
                                   shader::binomial_deliot2023(N, p, xi, xi),
                                   shader::binomial_single_gated(N, p, xi, xi),
                                   shader::binomial_single_gated_conditional(N, p, xi, xi),
                                   shader::binomial_dual_gated(N, p, xi, xi, false).x,
                                   shader::binomial_dual_gated(N, p, xi, xi, false).y,
                                   shader::binomial_dual_gated_conditional(N, p, xi, xi, true).x,
                                   shader::binomial_dual_gated_conditional(N, p, xi, xi, true).y};
                for (float x : v) EXPECT_TRUE(std::isfinite(x) && x >= 0.0f) << N << " " << p;
            }
        }
    }
}

// 003 Fig. 5: on p in [1e-16, 1] x N in [1, 1e16], wherever the true value is
// >= 1e-6 (so N p <= 13.8), the stable form's error is (a) the dropped O(p^2)
// term, relative N p epsilon / 2 <= 2e-3, plus (b) fp32 rounding of 1 - eps,
// relative 2^-24 / eps * N p <= 3e-3: <= 1 % with margin. The naive form
// returns 1 where the truth is e^-13.8, so its relative error is huge.
TEST(CountingLaws, StablePowWithinOnePercentWhereNaiveFails) {
    const PowAccuracy a = measure_pow_accuracy(256);
    EXPECT_LE(a.stable_rel_err_max, 0.01);
    EXPECT_GT(a.naive_rel_err_max, 1.0);
    EXPECT_GT(a.naive_abs_err_max, 0.9);  // 1 instead of ~0 (003 Fig. 5b)
    EXPECT_LT(a.stable_abs_err_max, 1e-3);
}

TEST(CountingLaws, DualGatedCountsSumToIntegerN) {
    Pcg32 rng(9u, 9u);
    for (float N : {0.0f, 1.0f, 2.0f, 3.0f, 17.0f, 1000.0f, 123456.0f}) {
        for (int i = 0; i < 20000; ++i) {
            const float p = rng.next_float(), xi1 = rng.next_float(), xi2 = rng.next_float();
            const glsl::vec2 c = shader::binomial_dual_gated(N, p, xi1, xi2, true);
            ASSERT_EQ(c.x + c.y, N) << "p=" << p;
            ASSERT_EQ(c.x, std::floor(c.x));
        }
    }
}

TEST(CountingLaws, ZirrLoopsOnlyBelowNpFive) {
    // Above N p = 5 the law ignores the trial uniforms (Gaussian branch).
    glsl::mat4 identity(1.0f), zeros(0.0f);
    EXPECT_EQ(shader::binomial_zirr2016(100.0f, 0.1f, 0.5f, identity),
              shader::binomial_zirr2016(100.0f, 0.1f, 0.5f, zeros));
    // Below, 4 trials of probability 0.5 all succeed with uniforms 0.
    EXPECT_EQ(shader::binomial_zirr2016(4.0f, 0.5f, 0.5f, glsl::mat4(0.0f)), 4.0f);
}

// Law 5b (binomial_single_gated_conditional, deliot2023's default): E[count]
// = N p for every real N and p. A count is [xi1 < gate] f(xi2), so
// E = gate x E[f(xi2)]: the gate in double (min(N p, 1 - (1 - p)^N)) times a
// midpoint quadrature of the draw over 2^16 values of xi2 with xi1 = 0 (the
// gate passes). Tolerance 2e-3 relative: the fp32 stable power of the law's
// gate is within Np eps / 2 + 2^-24 / eps relative of (1 - p)^N (003 Eq. 25,
// <= 1e-3 on this grid), the quadrature misses the normal tails beyond
// 2^-17 (< 1e-4 of the mean). Law 5 (Eq. 23) is checked to be > 20 % high at
// N p = 1, the bias this law removes.
TEST(CountingLaws, ConditionalSingleGatedIsUnbiased) {
    constexpr int kQuadrature = 1 << 16;
    auto mean_of = [&](float (*law)(float, float, float, float), double N, double p) {
        const double gate = std::min(N * p, 1.0 - std::pow(1.0 - p, N));
        double sum = 0.0;
        for (int k = 0; k < kQuadrature; ++k) {
            const float xi2 = static_cast<float>((k + 0.5) / kQuadrature);
            sum += law(static_cast<float>(N), static_cast<float>(p), 0.0f, xi2);
        }
        return gate * sum / kQuadrature;
    };
    for (double N : {0.3, 0.9, 1.0, 1.5, 3.0, 10.0, 40.0, 100.0, 1e3, 1e5, 1e9}) {
        for (double p : {1e-4, 0.01, 0.025, 0.1, 0.5, 0.9, 1.0}) {
            const double np = static_cast<double>(static_cast<float>(N)) *
                              static_cast<double>(static_cast<float>(p));
            const double mean = mean_of(shader::binomial_single_gated_conditional, N, p);
            EXPECT_NEAR(mean / np, 1.0, 2e-3) << "N " << N << " p " << p;
        }
    }
    EXPECT_GT(mean_of(shader::binomial_single_gated, 40.0, 0.025) / 1.0, 1.2);
    EXPECT_GT(mean_of(shader::binomial_single_gated, 400.0, 0.025) / 10.0, 1.05);
}

// The conditional law's clamped-Gaussian mean against a quadrature of the
// clamp, and its limits (sd 0, bounds far away).
TEST(CountingLaws, ClampedGaussianMeanMatchesQuadrature) {
    for (float mean : {1.0f, 1.3f, 2.5f, 3.9f}) {
        for (float sd : {0.05f, 0.6f, 2.0f}) {
            const float hi = 4.0f;
            double sum = 0.0;
            constexpr int kSteps = 1 << 16;
            for (int k = 0; k < kSteps; ++k) {
                const double x =
                    mean + sd * shader::normal_quantile(static_cast<float>((k + 0.5) / kSteps));
                sum += std::clamp(x, 1.0, static_cast<double>(hi));
            }
            EXPECT_NEAR(shader::clamped_gaussian_mean(mean, sd, 1.0f, hi), sum / kSteps, 2e-4)
                << mean << " " << sd;
        }
    }
    EXPECT_EQ(shader::clamped_gaussian_mean(2.0f, 0.0f, 1.0f, 4.0f), 2.0f);
    EXPECT_FLOAT_EQ(shader::clamped_gaussian_mean(1e6f, 1e3f, 1.0f, 1e35f), 1e6f);
    EXPECT_NEAR(shader::standard_normal_cdf(0.0f), 0.5f, 1e-7f);
    EXPECT_NEAR(shader::standard_normal_cdf(-1.0f), 0.15865525f, 2e-7f);
}

// Bounds 6 or more standard deviations away are skipped (their terms are
// below 1.7e-10 sd): near and on both sides of that cut the fp32 result
// agrees with the formula in double precision (std::erfc) to fp32 rounding of
// the mean plus erf_approx's error (1e-7 absolute, times |a| <= 6, plus
// rounding: 1e-6 sd), so the cut makes no step; a cut placed at 4 or less
// would miss a term of 8e-6 sd and fail here.
TEST(CountingLaws, ClampedGaussianMeanIsContinuousAtTheNegligibleTail) {
    const auto exact = [](double mean, double sd, double lo, double hi) {
        const double a = (lo - mean) / sd;
        const double b = (hi - mean) / sd;
        const auto phi = [](double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * M_PI); };
        const auto cdf = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
        return mean + sd * ((phi(a) + a * cdf(a)) - (phi(b) - b * (1.0 - cdf(b))));
    };
    for (float distance : {0.5f, 2.0f, 4.0f, 5.5f, 5.99f, 6.0f, 6.01f, 7.0f}) {
        for (float sd : {0.1f, 1.0f, 30.0f}) {
            // The lower bound `distance` sd below the mean; the upper far away.
            const float mean = 1.0f + distance * sd;
            EXPECT_NEAR(shader::clamped_gaussian_mean(mean, sd, 1.0f, 1e30f),
                        exact(mean, sd, 1.0, 1e30), 2e-7 * mean + 1e-6 * sd)
                << "below: distance " << distance << " sd " << sd;
            // The upper bound `distance` sd above the mean; the lower far away.
            const float hi = 1000.0f + distance * sd;
            EXPECT_NEAR(shader::clamped_gaussian_mean(1000.0f, sd, -1e30f, hi),
                        exact(1000.0, sd, -1e30, hi), 2e-7 * 1000.0 + 1e-6 * sd)
                << "above: distance " << distance << " sd " << sd;
        }
    }
}

}  // namespace
}  // namespace glintlab
