// Why a widened GGX lobe keeps LEAN's rule α'² = α² + 2σ² (core/slope_frame.glsl
// slope_widened_alpha). A footprint whose normals spread by a Gaussian of slope
// variance σ² per axis has the exact filtered slope distribution P ⊗ G_σ: the
// lobe's slopes plus the footprint's. For Beckmann that is Beckmann at
// α² + 2σ² exactly; GGX's slope variance is infinite, so no variance rule is
// exact for it, and the question is which single GGX lobe is closest. These
// tests compute P ⊗ G_σ by quadrature and find the GGX α' of least L1
// distance (the mass a single lobe puts in the wrong place).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include <fmt/format.h>

namespace glintlab {
namespace {

constexpr double kPi = std::numbers::pi;

// Slope distributions P22 of isotropic lobes (∫ P 2πr dr = 1).
double beckmann_slopes(double r, double alpha) {
    return std::exp(-r * r / (alpha * alpha)) / (kPi * alpha * alpha);
}
double ggx_slopes(double r, double alpha) {
    const double t = 1.0 + r * r / (alpha * alpha);
    return 1.0 / (kPi * alpha * alpha * t * t);
}

// e^(−x) I0(x), x ≥ 0: the ring average of a Gaussian, without overflow.
double scaled_bessel_i0(double x) {
    if (x < 600.0) return std::cyl_bessel_i(0.0, x) * std::exp(-x);
    return (1.0 + 1.0 / (8.0 * x) + 9.0 / (128.0 * x * x)) / std::sqrt(2.0 * kPi * x);
}

// A radial grid r = scale tan(v π/2), v at midpoints of [0, 1): resolves the
// peak at any scale and reaches GGX's r⁻⁴ tail; weights are 2πr dr.
struct RadialGrid {
    std::vector<double> r, area;
    RadialGrid(double scale, int n) {
        for (int i = 0; i < n; ++i) {
            const double v = (i + 0.5) / n;
            const double c = std::cos(0.5 * kPi * v);
            r.push_back(scale * std::tan(0.5 * kPi * v));
            area.push_back(2.0 * kPi * r.back() * scale * 0.5 * kPi / (c * c) / n);
        }
    }
};

// (P ⊗ G_σ)(r) on `out`: ∫ P(ρ) (1/σ²) e^(−(r² + ρ²)/2σ²) I0(rρ/σ²) ρ dρ, the
// Gaussian's integral over the ring of radius ρ around r.
std::vector<double> convolved(const std::function<double(double)>& p, double sigma2,
                              const RadialGrid& in, const RadialGrid& out) {
    std::vector<double> c(out.r.size(), 0.0);
    for (size_t i = 0; i < out.r.size(); ++i) {
        const double r = out.r[i];
        double sum = 0.0;
        for (size_t j = 0; j < in.r.size(); ++j) {
            const double rho = in.r[j], d = r - rho;
            sum += p(rho) * std::exp(-d * d / (2.0 * sigma2)) * scaled_bessel_i0(r * rho / sigma2) /
                   sigma2 * in.area[j] / (2.0 * kPi);
        }
        c[i] = sum;
    }
    return c;
}

double l1_distance(const std::vector<double>& c, const RadialGrid& g,
                   const std::function<double(double)>& lobe) {
    double sum = 0.0;
    for (size_t i = 0; i < g.r.size(); ++i) sum += std::abs(c[i] - lobe(g.r[i])) * g.area[i];
    return sum;
}

struct Fit {
    double gain;     // (α'² − α²) / (2σ²) of the closest lobe: 1 is LEAN's rule
    double best_l1;  // its L1 distance
    double lean_l1;  // the L1 distance of α² + 2σ²
    double mass;     // ∫ P ⊗ G_σ on the grid (1 up to quadrature)
};

Fit closest_lobe(double (*slopes)(double, double), double alpha, double sigma2) {
    const double alpha2 = alpha * alpha;
    const RadialGrid in(alpha, 1024), out(std::sqrt(alpha2 + 2.0 * sigma2), 384);
    const std::vector<double> c =
        convolved([&](double r) { return slopes(r, alpha); }, sigma2, in, out);
    auto l1_at_gain = [&](double gain) {
        const double a = std::sqrt(alpha2 + 2.0 * gain * sigma2);
        return l1_distance(c, out, [&](double r) { return slopes(r, a); });
    };
    // Golden-section search over the gain in [0.25, 4]; the distance is
    // unimodal in it (one crossing of the two profiles moves monotonically).
    double lo = 0.25, hi = 4.0;
    const double k = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = hi - k * (hi - lo), b = lo + k * (hi - lo), fa = l1_at_gain(a), fb = l1_at_gain(b);
    for (int i = 0; i < 60; ++i) {
        if (fa < fb) {
            hi = b, b = a, fb = fa, a = hi - k * (hi - lo), fa = l1_at_gain(a);
        } else {
            lo = a, a = b, fa = fb, b = lo + k * (hi - lo), fb = l1_at_gain(b);
        }
    }
    double mass = 0.0;
    for (size_t i = 0; i < c.size(); ++i) mass += c[i] * out.area[i];
    const double gain = 0.5 * (lo + hi);
    return {gain, l1_at_gain(gain), l1_at_gain(1.0), mass};
}

const double kSpreads[] = {0.1, 0.5, 2.0};  // σ²/α²: narrow to wide against the lobe

TEST(SlopeWidening, BeckmannConvolvedWithAGaussianIsTheWidenedBeckmann) {
    // The harness on the case with a closed form: the closest Beckmann lobe
    // is α² + 2σ² itself and the distance vanishes to quadrature error
    // (measured < 1e-5; a wrong factor of 2 in the rule misplaces ≥ 10 %).
    for (double spread : kSpreads) {
        const double alpha = 0.15;
        const Fit f = closest_lobe(beckmann_slopes, alpha, spread * alpha * alpha);
        SCOPED_TRACE(fmt::format("sigma2/alpha2 {}", spread));
        EXPECT_NEAR(f.mass, 1.0, 1e-4);
        EXPECT_NEAR(f.gain, 1.0, 0.01);
        EXPECT_LT(f.lean_l1, 1e-3);
    }
}

TEST(SlopeWidening, GgxConvolvedWithAGaussianIsClosestToTheLeanRule) {
    // GGX ⊗ G_σ has no GGX form; its closest single GGX lobe in L1 has a
    // gain of 0.92-1.05 over σ²/α² = 0.1-2 (measured 1.048, 1.011, 0.922),
    // and the rule's own distance (0.061, 0.165, 0.266: a single GGX lobe
    // misplaces up to 13 % of the mass) is within 0.0024 of that optimum's.
    // A rule that matched the peak value instead (gain 1.25-1.76 here, 2 as
    // σ → 0: GGX's curvature at its peak is twice Beckmann's) is farther.
    // So the rule is kept for GGX: its larger errors on real normal maps
    // come from footprints whose slopes are far from one Gaussian
    // (docs/MODELS.md, "Which filtering"), which no single-lobe rule follows.
    for (double spread : kSpreads) {
        const double alpha = 0.15;
        const Fit f = closest_lobe(ggx_slopes, alpha, spread * alpha * alpha);
        SCOPED_TRACE(fmt::format("sigma2/alpha2 {}", spread));
        RecordProperty(fmt::format("gain_{}", spread), fmt::format("{:.3f}", f.gain));
        RecordProperty(fmt::format("lean_l1_{}", spread), fmt::format("{:.4f}", f.lean_l1));
        RecordProperty(fmt::format("best_l1_{}", spread), fmt::format("{:.4f}", f.best_l1));
        // GGX's r⁻⁴ tail leaves a little mass beyond the grid's reach.
        EXPECT_NEAR(f.mass, 1.0, 2e-3);
        EXPECT_GT(f.gain, 0.85);
        EXPECT_LT(f.gain, 1.12);
        EXPECT_LT(f.lean_l1 - f.best_l1, 5e-3);
    }
}

}  // namespace
}  // namespace glintlab
