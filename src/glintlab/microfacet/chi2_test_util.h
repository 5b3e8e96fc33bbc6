// Pearson chi-square goodness-of-fit test of a direction sampler against its
// claimed solid-angle density, for the microfacet tests (design of pbrt-v4
// bsdfs_test.cpp and Mitsuba's chi2.py): directions are binned in
// (cos theta, phi), where d(omega) = d(cos theta) d(phi), so the expected count
// of a cell is N times the integral of the pdf over the cell, computed with
// nested adaptive Simpson quadrature in double. Cells expecting fewer than 5 samples
// are pooled (the chi-square approximation needs about 5 per cell), and one
// more cell counts the samples the sampler rejected against
// N (1 - integral of the pdf), so a sampler whose success probability
// disagrees with its pdf's mass fails too.
#pragma once

#include <algorithm>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/glm.hpp>

#include "glintlab/core/rng.h"

namespace glintlab::testing {

struct Chi2Result {
    double statistic = 0.0;
    int dof = 0;
    double p_value = 0.0;
    double pdf_mass = 0.0;  // integral of the pdf over the binned domain
    long accepted = 0;      // samples the sampler returned
    std::string describe() const {
        return fmt::format("chi2 = {:.1f}, dof = {}, p = {:.3g}, pdf mass = {:.5f}, accepted = {}",
                           statistic, dof, p_value, pdf_mass, accepted);
    }
};

struct Chi2Config {
    int n_cos = 64;
    int n_phi = 128;
    double tolerance = 1e-8;  // absolute error target of each cell's pdf integral
    int max_depth = 6;        // adaptive Simpson recursion limit per axis
    long samples = 1000000;
    bool full_sphere = true;  // cos theta in [-1, 1], else [0, 1]
    uint64_t seed = 1;
};

// Adaptive Simpson quadrature of g on [a, b] with Richardson termination
// (|S2 - S1| <= 15 eps); depth-limited so that discontinuities cost bounded work.
template <class G>
double adaptive_simpson_step(const G& g, double a, double b, double fa, double fm, double fb,
                             double whole, double eps, int depth) {
    const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
    const double flm = g(lm), frm = g(rm);
    const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    const double delta = left + right - whole;
    if (depth <= 0 || std::abs(delta) <= 15.0 * eps) return left + right + delta / 15.0;
    return adaptive_simpson_step(g, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1) +
           adaptive_simpson_step(g, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1);
}

template <class G>
double adaptive_simpson(const G& g, double a, double b, double eps, int depth) {
    const double fa = g(a), fm = g(0.5 * (a + b)), fb = g(b);
    const double whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    return adaptive_simpson_step(g, a, b, fa, fm, fb, whole, eps, depth);
}

// Significance of one of `tests` independent tests so that the family-wise
// false-failure rate is `alpha` (Sidak correction).
inline double sidak_significance(double alpha, int tests) {
    return 1.0 - std::pow(1.0 - alpha, 1.0 / tests);
}

inline glm::vec3 direction_from(double cos_t, double phi) {
    const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
    return glm::vec3(float(sin_t * std::cos(phi)), float(sin_t * std::sin(phi)), float(cos_t));
}

inline Chi2Result chi2_test(const std::function<float(glm::vec3)>& pdf,
                            const std::function<std::optional<glm::vec3>(Pcg32&)>& sampler,
                            const Chi2Config& cfg) {
    const double z0 = cfg.full_sphere ? -1.0 : 0.0;
    const double dz = (1.0 - z0) / cfg.n_cos;
    const double dphi = 2.0 * std::numbers::pi / cfg.n_phi;
    const int cells = cfg.n_cos * cfg.n_phi;

    // Observed counts.
    std::vector<double> observed(cells, 0.0);
    Pcg32 rng(cfg.seed, 0x5eed);
    long accepted = 0;
    for (long i = 0; i < cfg.samples; ++i) {
        const std::optional<glm::vec3> w = sampler(rng);
        if (!w) continue;
        ++accepted;
        const glm::dvec3 d = glm::normalize(glm::dvec3(*w));
        double phi = std::atan2(d.y, d.x);
        if (phi < 0.0) phi += 2.0 * std::numbers::pi;
        const int iz = std::clamp(int((d.z - z0) / dz), 0, cfg.n_cos - 1);
        const int ip = std::clamp(int(phi / dphi), 0, cfg.n_phi - 1);
        observed[iz * cfg.n_phi + ip] += 1.0;
    }

    // Expected counts: nested adaptive Simpson per cell (the pdfs have kinks,
    // e.g. where wo.m = 0, that a fixed grid resolves only to O(h) overall).
    auto pdf_at = [&](double z, double phi) { return double(pdf(direction_from(z, phi))); };
    std::vector<double> expected(cells, 0.0);
    double mass = 0.0;
    for (int cz = 0; cz < cfg.n_cos; ++cz)
        for (int cp = 0; cp < cfg.n_phi; ++cp) {
            const double za = z0 + cz * dz, pa = cp * dphi;
            const double integral = adaptive_simpson(
                [&](double z) {
                    return adaptive_simpson([&](double phi) { return pdf_at(z, phi); }, pa,
                                            pa + dphi, cfg.tolerance / dz, cfg.max_depth);
                },
                za, za + dz, cfg.tolerance, cfg.max_depth);
            mass += integral;
            expected[cz * cfg.n_phi + cp] = integral * double(cfg.samples);
        }
    // The rejected samples form one more cell.
    observed.push_back(double(cfg.samples - accepted));
    expected.push_back(std::max(0.0, 1.0 - mass) * double(cfg.samples));

    // Pool the cells expecting < 5 samples; fold the pool into the smallest
    // retained cell if it is still too small.
    std::vector<std::pair<double, double>> bins;  // (expected, observed)
    double pool_e = 0.0, pool_o = 0.0;
    for (size_t i = 0; i < expected.size(); ++i) {
        if (expected[i] < 5.0) {
            pool_e += expected[i];
            pool_o += observed[i];
        } else {
            bins.emplace_back(expected[i], observed[i]);
        }
    }
    if (pool_e >= 5.0) {
        bins.emplace_back(pool_e, pool_o);
    } else if (!bins.empty()) {
        auto it = std::min_element(bins.begin(), bins.end());
        it->first += pool_e;
        it->second += pool_o;
    }
    Chi2Result r;
    r.pdf_mass = mass;
    r.accepted = accepted;
    for (const auto& [e, o] : bins) r.statistic += (o - e) * (o - e) / e;
    r.dof = int(bins.size()) - 1;
    r.p_value = r.dof > 0 ? boost::math::gamma_q(0.5 * r.dof, 0.5 * r.statistic) : 1.0;
    return r;
}

}  // namespace glintlab::testing
