#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "glintlab/core/rng.h"
#include "glintlab/counting/exact_binomial.h"
#include "glintlab/counting/laws.h"

namespace glintlab {
namespace {

TEST(CountingMultinomial, CountsAreNonNegativeIntegersSummingToN) {
    Pcg32 rng(21u, 4u);
    for (float N : {0.0f, 1.0f, 2.0f, 3.0f, 10.0f, 257.0f, 1e6f}) {
        for (int i = 0; i < 20000; ++i) {
            const glsl::vec4 probs(rng.next_float(), rng.next_float(), rng.next_float(),
                                   rng.next_float());
            const glsl::vec4 a(rng.next_float(), rng.next_float(), rng.next_float(), 0.0f);
            const glsl::vec4 b(rng.next_float(), rng.next_float(), rng.next_float(), 0.0f);
            const glsl::vec4 c = shader::multinomial4(N, probs, a, b);
            for (int k = 0; k < 4; ++k) {
                ASSERT_GE(c[k], 0.0f);
                ASSERT_EQ(c[k], std::floor(c[k]));
            }
            ASSERT_EQ(c.x + c.y + c.z + c.w, N);
        }
    }
}

TEST(CountingMultinomial, EightBinsSumToN) {
    Pcg32 rng(22u, 4u);
    for (float N : {1.0f, 2.0f, 5.0f, 4096.0f}) {
        for (int i = 0; i < 5000; ++i) {
            glsl::vec4 u[6];
            for (auto& v : u)
                v = glsl::vec4(rng.next_float(), rng.next_float(), rng.next_float(),
                               rng.next_float());
            glsl::vec4 ca, cb;
            shader::multinomial8(N, u[0], u[1], u[2], u[3], u[4], u[5], ca, cb);
            float sum = 0.0f;
            for (int k = 0; k < 4; ++k) {
                ASSERT_GE(ca[k], 0.0f);
                ASSERT_GE(cb[k], 0.0f);
                sum += ca[k] + cb[k];
            }
            ASSERT_EQ(sum, N);
        }
    }
}

// Marginal k of Multinomial(N, p) is Bin(N, p_k). The hierarchy uses
// dual-gated binomials, exact for N <= 2 and Gaussian beyond, so:
//  - N = 2: chi-square of each marginal against Bin(2, p_k) (3 outcomes,
//    2 degrees of freedom, critical value 13.8 at significance 1e-3);
//  - N = 400: mean within 4 standard errors plus the law's known bias of at
//    most one count per level (dual gating centres the Gaussian on
//    1 + (N - 2) q, not N q: |1 - 2q| <= 1 per level, <= 3 levels), and TV
//    against Bin(N, p_k) over bins of 2 counts <= 0.5 / sigma + noise (the
//    shifted-Gaussian bound of validate_counting.cpp) with sigma >= 6.
TEST(CountingMultinomial, MarginalsAreBinomial) {
    const glsl::vec4 probs(0.1f, 0.2f, 0.3f, 0.4f);
    const int n = 100000;
    for (float N : {2.0f, 400.0f}) {
        std::vector<std::vector<double>> hist(4, std::vector<double>(static_cast<size_t>(N) + 1));
        Pcg32 rng(7u, static_cast<uint64_t>(N));
        for (int i = 0; i < n; ++i) {
            const glsl::vec4 a(rng.next_float(), rng.next_float(), rng.next_float(), 0.0f);
            const glsl::vec4 b(rng.next_float(), rng.next_float(), rng.next_float(), 0.0f);
            const glsl::vec4 c = shader::multinomial4(N, probs, a, b);
            for (int k = 0; k < 4; ++k) hist[k][static_cast<size_t>(c[k])] += 1.0;
        }
        for (int k = 0; k < 4; ++k) {
            const BinomialReference ref(N, probs[k]);
            if (N == 2.0f) {
                double chi2 = 0.0;
                for (int j = 0; j <= 2; ++j) {
                    const double e = n * ref.pmf(j);
                    chi2 += (hist[k][j] - e) * (hist[k][j] - e) / e;
                }
                EXPECT_LT(chi2, 13.8) << "bin " << k;
                continue;
            }
            double mean = 0.0, tv = 0.0;
            for (size_t j = 0; j < hist[k].size(); ++j) mean += j * hist[k][j] / n;
            const double se = std::sqrt(ref.variance() / n);
            EXPECT_NEAR(mean, N * probs[k], 3.0 + 4.0 * se) << "bin " << k;
            for (size_t j = 0; j < hist[k].size(); j += 2) {
                const double h = (hist[k][j] + (j + 1 < hist[k].size() ? hist[k][j + 1] : 0.0)) / n;
                tv += std::abs(h - ref.pmf(static_cast<int64_t>(j)) -
                               ref.pmf(static_cast<int64_t>(j) + 1));
            }
            EXPECT_LE(0.5 * tv, 0.5 / std::sqrt(ref.variance()) + 0.01) << "bin " << k;
        }
    }
}

}  // namespace
}  // namespace glintlab
