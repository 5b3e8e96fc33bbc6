#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "glintlab/core/error.h"
#include "glintlab/core/rng.h"
#include "glintlab/counting/exact_binomial.h"

namespace glintlab {
namespace {

TEST(CountingExactBinomial, PmfSumsToOneAndHasTheMixtureMoments) {
    for (double N : {0.0, 0.3, 1.0, 2.5, 10.0, 1000.0, 1e6}) {
        for (double p : {0.0, 1e-7, 0.01, 0.5, 0.9, 1.0}) {
            const BinomialReference ref(N, p);
            double sum = 0.0, mean = 0.0, m2 = 0.0;
            for (int64_t k = ref.first(); k <= ref.last(); ++k) {
                sum += ref.pmf(k);
                mean += k * ref.pmf(k);
            }
            for (int64_t k = ref.first(); k <= ref.last(); ++k)
                m2 += (k - mean) * (k - mean) * ref.pmf(k);
            // Rounding of up to ~1e5 double terms: 1e-9 relative is generous.
            EXPECT_NEAR(sum, 1.0, 1e-9) << N << " " << p;
            EXPECT_NEAR(mean, N * p, 1e-9 * std::max(1.0, N * p)) << N << " " << p;
            EXPECT_NEAR(m2, ref.variance(), 1e-8 * std::max(1.0, ref.variance())) << N << " " << p;
        }
    }
}

TEST(CountingExactBinomial, RealNIsTheMixtureOfNeighbours) {
    // 003 §6: N = 2.25 mixes Bin(2, p) (weight 0.75) and Bin(3, p) (0.25).
    const double p = 0.3;
    const BinomialReference mix(2.25, p), two(2.0, p), three(3.0, p);
    for (int64_t k = 0; k <= 3; ++k)
        EXPECT_NEAR(mix.pmf(k), 0.75 * two.pmf(k) + 0.25 * three.pmf(k), 1e-15);
}

// Inversion sampling against the pmf: chi-square over the 16 counts of
// Bin(15, 0.4) merged to >= 5 expected; at significance 1e-3 with <= 15
// degrees of freedom the critical value is 37.7 (fixed seed: deterministic).
TEST(CountingExactBinomial, SamplerFollowsThePmf) {
    const BinomialReference ref(15.0, 0.4);
    Pcg32 rng(3u, 5u);
    const int n = 200000;
    std::vector<double> counts(16, 0.0);
    for (int i = 0; i < n; ++i) counts[static_cast<size_t>(ref.sample(rng.next_double()))] += 1.0;
    double chi2 = 0.0, e = 0.0, o = 0.0;
    for (int k = 0; k <= 15; ++k) {
        e += n * ref.pmf(k);
        o += counts[static_cast<size_t>(k)];
        if (e >= 5.0 || k == 15) {
            chi2 += (o - e) * (o - e) / e;
            e = o = 0.0;
        }
    }
    EXPECT_LT(chi2, 37.7);
}

TEST(CountingExactBinomial, RejectsOutOfRangeParameters) {
    EXPECT_THROW(BinomialReference(-1.0, 0.5), Error);
    EXPECT_THROW(BinomialReference(10.0, 1.5), Error);
    EXPECT_THROW(BinomialReference(NAN, 0.5), Error);
}

}  // namespace
}  // namespace glintlab
