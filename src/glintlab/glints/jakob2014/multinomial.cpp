#include "glintlab/glints/jakob2014/multinomial.h"

#include <algorithm>
#include <cmath>

#include "glintlab/glints/jakob2014/tea.h"

namespace glintlab::jakob2014 {
namespace {

constexpr uint32_t kCountSalt = 0x636f756eu;  // "coun"
constexpr uint32_t kAreaSalt = 0x61726561u;   // "area"

// Category of u in [0, 1) under the cumulative probabilities of p; categories
// with p_i = 0 are never chosen.
int categorical(const std::array<double, 4>& p, double u) {
    double c = 0.0;
    int last = 0;
    for (int i = 0; i < 4; ++i) {
        if (p[i] <= 0.0) continue;
        last = i;
        c += p[i];
        if (u < c) return i;
    }
    return last;  // rounding of the cumulative sum
}

// Gamma(k, 1) for integer k >= 1: Marsaglia & Tsang 2000 (exact rejection).
double sample_gamma(double k, TeaStream& rng) {
    const double d = k - 1.0 / 3.0;
    const double c = 1.0 / std::sqrt(9.0 * d);
    for (;;) {
        double x, v;
        do {
            x = rng.next_normal();
            v = 1.0 + c * x;
        } while (v <= 0.0);
        v = v * v * v;
        const double u = rng.next_open();
        if (std::log(u) < 0.5 * x * x + d - d * v + d * std::log(v)) return d * v;
    }
}

}  // namespace

std::array<int64_t, 4> sample_multinomial4(int64_t n, const std::array<double, 4>& p,
                                           uint64_t node_id, uint32_t seed) {
    std::array<int64_t, 4> x{0, 0, 0, 0};
    if (n <= 0) return x;
    TeaStream rng(node_id, seed, kCountSalt);
    if (n <= 8) {
        if (p[0] == 0.25 && p[1] == 0.25 && p[2] == 0.25 && p[3] == 0.25) {
            // Spatial splits: each draw is uniform over 4 children, i.e. two
            // random bits; one TEA call gives all (at most 8) draws.
            uint64_t bits = (uint64_t(rng.next_u32()) << 32u) | rng.next_u32();
            for (int64_t k = 0; k < n; ++k, bits >>= 2u) ++x[bits & 3u];
            return x;
        }
        for (int64_t k = 0; k < n; ++k) ++x[categorical(p, rng.next_double())];
        return x;
    }
    // X = n p + sqrt(n) W with W_j = sqrt(p_j) Z_j - p_j sum_k sqrt(p_k) Z_k:
    // Cov(W) = diag p - p p^T and sum_j W_j = 0 (the multinomial's covariance).
    std::array<double, 4> sz{};  // sqrt(p_j) Z_j
    double s = 0.0;              // sum_k sqrt(p_k) Z_k
    for (int i = 0; i < 4; ++i) {
        const double sp = std::sqrt(std::max(0.0, p[i]));
        const double z = rng.next_normal();
        sz[i] = sp * z;
        s += sp * z;
    }
    const double nd = static_cast<double>(n), sn = std::sqrt(nd);
    int64_t sum = 0;
    for (int i = 0; i < 4; ++i) {
        if (p[i] <= 0.0) continue;
        const double w = sz[i] - p[i] * s;
        const double xi = std::nearbyint(nd * p[i] + sn * w);
        x[i] = xi <= 0.0 ? 0 : (xi >= nd ? n : static_cast<int64_t>(xi));
        sum += x[i];
    }
    // Fix-up: components drawn with probability p_i move the sum towards n.
    while (sum != n) {
        const int i = categorical(p, rng.next_double());
        if (sum < n) {
            ++x[i];
            ++sum;
        } else if (x[i] > 0) {
            --x[i];
            --sum;
        }
    }
    return x;
}

std::array<double, 4> sample_dirichlet4(const std::array<int64_t, 4>& k, uint64_t node_id,
                                        uint32_t seed, uint32_t channel) {
    TeaStream rng(node_id, seed, kAreaSalt + channel * 0x9e3779b9u);
    std::array<double, 4> g{};
    double total = 0.0;
    for (int i = 0; i < 4; ++i) {
        g[i] = k[i] > 0 ? sample_gamma(static_cast<double>(k[i]), rng) : 0.0;
        total += g[i];
    }
    if (total > 0.0)
        for (double& v : g) v /= total;
    return g;
}

}  // namespace glintlab::jakob2014
