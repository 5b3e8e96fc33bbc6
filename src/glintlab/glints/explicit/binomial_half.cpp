#include "glintlab/glints/explicit/binomial_half.h"

#include <bit>
#include <cmath>

namespace glintlab::explicit_gt {
namespace {

// fc(k) = ln k! - [(k + 1/2) ln(k + 1) - (k + 1) + ln sqrt(2 pi)], the
// Stirling remainder of Hörmann 1993 (tabulated for k <= 9, series above).
double stirling_tail(double k) {
    static constexpr double kTable[10] = {
        0.08106146679532726,  0.04134069595540929, 0.02767792568499834, 0.02079067210376509,
        0.01664469118982119,  0.01387612882307075, 0.01189670994589177, 0.01041126526197209,
        0.009255462182712733, 0.008330563433362871};
    if (k <= 9.0) return kTable[static_cast<int>(k)];
    const double kp1 = k + 1.0, kp1sq = kp1 * kp1;
    return (1.0 / 12.0 - (1.0 / 360.0 - 1.0 / 1260.0 / kp1sq) / kp1sq) / kp1;
}

int64_t popcount_binomial(int64_t n, Pcg32& rng) {
    int64_t k = 0;
    for (; n >= 32; n -= 32) k += std::popcount(rng.next_uint());
    if (n > 0) k += std::popcount(rng.next_uint() >> (32 - n));
    return k;
}

// BTRS (Hörmann 1993, algorithm BTRS, steps 1-3.4) for p = 1/2 (so q = p,
// r = p/q = 1 and the (k - m) ln r term vanishes).
int64_t btrs_binomial_half(int64_t n_int, Pcg32& rng) {
    const double n = static_cast<double>(n_int), p = 0.5;
    const double spq = std::sqrt(n * p * (1.0 - p));
    const double b = 1.15 + 2.53 * spq;
    const double a = -0.0873 + 0.0248 * b + 0.01 * p;
    const double c = n * p + 0.5;
    const double v_r = 0.92 - 4.2 / b;
    const double alpha = (2.83 + 5.1 / b) * spq;
    const double m = std::floor((n + 1.0) * p);
    for (;;) {
        const double u = rng.next_double() - 0.5;
        double v = rng.next_double();
        const double us = 0.5 - std::abs(u);
        const double k = std::floor((2.0 * a / us + b) * u + c);
        // Step 2: squeeze (the box under the density).
        if (us >= 0.07 && v <= v_r) return static_cast<int64_t>(k);
        // Step 3: outside the support.
        if (k < 0.0 || k > n) continue;
        // Steps 3.1-3.4: ln(v alpha / (a / us^2 + b)) <= ln f(k) - ln f(m).
        v = std::log(v * alpha / (a / (us * us) + b));
        const double log_ratio = (m + 0.5) * std::log((m + 1.0) / (n - m + 1.0)) +
                                 (n + 1.0) * std::log((n - m + 1.0) / (n - k + 1.0)) +
                                 (k + 0.5) * std::log((n - k + 1.0) / (k + 1.0)) +
                                 stirling_tail(m) + stirling_tail(n - m) - stirling_tail(k) -
                                 stirling_tail(n - k);
        if (v <= log_ratio) return static_cast<int64_t>(k);
    }
}

}  // namespace

int64_t sample_binomial_half(int64_t n, Pcg32& rng) {
    if (n <= 0) return 0;
    if (n <= 256) return popcount_binomial(n, rng);
    return btrs_binomial_half(n, rng);
}

}  // namespace glintlab::explicit_gt
