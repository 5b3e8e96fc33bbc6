#include "glintlab/counting/cell_statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "glintlab/core/rng.h"

namespace glintlab {
namespace {

// A random permutation of 0..n-1 (Fisher-Yates).
std::vector<uint32_t> permutation(int n, Pcg32& rng) {
    std::vector<uint32_t> v(static_cast<size_t>(n));
    std::iota(v.begin(), v.end(), 0u);
    for (uint32_t i = static_cast<uint32_t>(n) - 1; i > 0; --i)
        std::swap(v[i], v[rng.next_uint(i + 1)]);
    return v;
}

}  // namespace

CellStatistics measure_cell(CountingLaw law, const BinomialReference& reference, int samples,
                            uint64_t seed) {
    CellStatistics s;
    s.N = reference.trials();
    s.p = reference.probability();
    s.ref_mean = reference.mean();
    s.ref_variance = reference.variance();
    // Bins: integers while sigma <= 5. Wider laws merge ceil(sigma / 5)
    // integers per bin: with n samples the expected TV estimate of a perfect
    // sampler is about 0.5 sum_b sqrt(2 P_b / (pi n)) ~ 0.0028 sqrt(sigma / w)
    // for n = 1e5, so per-integer bins at sigma = 500 would report 0.06 of pure
    // noise; ~5 bins per sigma keep it near 0.006 while still resolving the
    // shape of the law (a binomial varies on the scale of sigma, not of 1).
    const double sigma = std::sqrt(s.ref_variance);
    s.bin_width = sigma <= 5.0 ? 1 : static_cast<int64_t>(std::ceil(sigma / 5.0));
    const int64_t first = reference.first();
    const int64_t bins = (reference.last() - first) / s.bin_width + 1;
    std::vector<double> histogram(static_cast<size_t>(bins), 0.0);
    double outside = 0.0;

    Pcg32 rng(mix_bits(seed), mix_bits(seed ^ 0x5bd1e995u));
    // Latin hypercube (McKay et al. 1979): sample i uses xi1 in stratum
    // perm1[i] and xi2 in stratum perm2[i]. Each sample is still uniform, so
    // the output still follows the law, while the gating noise of the mean and
    // of the histogram drops well below that of independent draws.
    const std::vector<uint32_t> perm1 = permutation(samples, rng);
    const std::vector<uint32_t> perm2 = permutation(samples, rng);
    const double inv = 1.0 / samples;
    double sum = 0.0, sum2 = 0.0;  // of x - ref_mean, to avoid cancellation
    for (int i = 0; i < samples; ++i) {
        const LawUniforms xi{(perm1[static_cast<size_t>(i)] + rng.next_double()) * inv,
                             (perm2[static_cast<size_t>(i)] + rng.next_double()) * inv};
        const double x = sample_count(law, s.N, s.p, xi, rng, &reference);
        if (!std::isfinite(x) || x < 0.0) {
            ++s.invalid;
            outside += 1.0;
            continue;
        }
        const double d = x - s.ref_mean;
        sum += d;
        sum2 += d * d;
        const auto k = static_cast<int64_t>(std::floor(x + 0.5));
        if (k < first || k > reference.last()) {
            outside += 1.0;
        } else {
            histogram[static_cast<size_t>((k - first) / s.bin_width)] += 1.0;
        }
    }
    const double valid = samples - static_cast<double>(s.invalid);
    if (valid > 0) {
        s.mean = s.ref_mean + sum / valid;
        s.variance = std::max(0.0, sum2 / valid - (sum / valid) * (sum / valid));
    } else {
        s.mean = s.variance = std::nan("");
    }
    double tv = outside * inv;  // mass the reference gives (almost) none
    for (int64_t b = 0; b < bins; ++b) {
        double ref = 0.0;
        for (int64_t k = first + b * s.bin_width;
             k < std::min(first + (b + 1) * s.bin_width, reference.last() + 1); ++k)
            ref += reference.pmf(k);
        tv += std::abs(histogram[static_cast<size_t>(b)] * inv - ref);
    }
    s.tv = 0.5 * tv;
    return s;
}

}  // namespace glintlab
