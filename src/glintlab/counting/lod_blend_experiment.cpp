#include "glintlab/counting/lod_blend_experiment.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/distributions/chi_squared.hpp>

#include "glintlab/core/rng.h"
#include "glintlab/counting/exact_binomial.h"
#include "glintlab/counting/laws.h"

namespace glintlab {
namespace {

constexpr int kGrid = 32;                       // texels per side of the domain
constexpr int kBottom = 8 * 8, kTop = 16 * 16;  // trials of the two LOD cells
constexpr int kWindowW = 16, kWindowH = 7;      // window in texels
constexpr int kWindow = kWindowW * kWindowH;    // 112 trials

// Chi-square goodness of fit of integer samples to `law`; p-value.
double chi_square_p(const std::vector<int64_t>& samples, const BinomialReference& law) {
    const double n = static_cast<double>(samples.size());
    std::vector<double> observed(static_cast<size_t>(law.last() - law.first() + 1), 0.0);
    for (int64_t k : samples) {
        const int64_t c = std::clamp(k, law.first(), law.last());
        observed[static_cast<size_t>(c - law.first())] += 1.0;
    }
    // Merge neighbouring counts into bins of >= 5 expected samples; the
    // tails beyond the table fall into the end bins (clamped above).
    double chi2 = 0.0, e = 0.0, o = 0.0;
    int bins = 0;
    for (int64_t k = law.first(); k <= law.last(); ++k) {
        e += n * law.pmf(k);
        o += observed[static_cast<size_t>(k - law.first())];
        if (e >= 5.0) {
            chi2 += (o - e) * (o - e) / e;
            ++bins;
            e = o = 0.0;
        }
    }
    if (e > 0.0 || o > 0.0) {  // remainder: into the last bin's statistic
        chi2 += (o - e) * (o - e) / std::max(e, 1e-300);
        ++bins;
    }
    if (bins < 2) return 1.0;
    const boost::math::chi_squared_distribution<double> dist(bins - 1);
    return boost::math::cdf(boost::math::complement(dist, chi2));
}

double sample_variance(const std::vector<int64_t>& v) {
    double m = 0.0, m2 = 0.0;
    for (int64_t x : v) m += static_cast<double>(x);
    m /= static_cast<double>(v.size());
    for (int64_t x : v) m2 += (static_cast<double>(x) - m) * (static_cast<double>(x) - m);
    return m2 / static_cast<double>(v.size() - 1);
}

}  // namespace

LodBlendResult run_lod_blend_experiment(double p, int samples, uint64_t seed) {
    LodBlendResult r;
    r.p = p;
    r.samples = samples;
    const double area_bottom = kBottom, area_top = kTop, area = kWindow;  // in texels
    const double w_top = shader::lod_top_weight(
        static_cast<float>(area), static_cast<float>(area_top), static_cast<float>(area_bottom));
    const glsl::vec2 split = shader::distributed_binomial_trials(1.0f, static_cast<float>(area),
                                                                 static_cast<float>(area_top),
                                                                 static_cast<float>(area_bottom));
    const BinomialReference truth_law(kWindow, p), top(kTop, p), bottom(kBottom, p);
    const BinomialReference top_part(split.x, p), bottom_part(split.y, p);
    const BinomialReference window_trials(kGrid * kGrid, area / (kGrid * kGrid));

    std::vector<BinomialReference> per_trials;  // Bin(t, p) for each possible trial count t
    for (int64_t t = window_trials.first(); t <= window_trials.last(); ++t)
        per_trials.emplace_back(static_cast<double>(t), p);

    Pcg32 rng(mix_bits(seed), mix_bits(seed + 0x632be59bd9b4e019ULL));
    std::vector<int64_t> truth, distributed, blend, uniform;
    for (int i = 0; i < samples; ++i) {
        // Truth: a stratified facet per texel (position jittered in its texel,
        // oriented to reflect with probability p); the window is texel-aligned
        // at a random texel, so it holds exactly the facets of its texels.
        const int x0 = static_cast<int>(rng.next_uint(kGrid - kWindowW + 1));
        const int y0 = static_cast<int>(rng.next_uint(kGrid - kWindowH + 1));
        // Only the window's texels and a one-texel border are simulated: a
        // facet stays inside its texel, so farther texels never contribute.
        int64_t count = 0;
        for (int y = std::max(y0 - 1, 0); y < std::min(y0 + kWindowH + 1, kGrid); ++y) {
            for (int x = std::max(x0 - 1, 0); x < std::min(x0 + kWindowW + 1, kGrid); ++x) {
                const float fx = static_cast<float>(x) + rng.next_float();
                const float fy = static_cast<float>(y) + rng.next_float();
                const bool reflects = rng.next_double() < p;
                if (reflects && fx >= x0 && fx < x0 + kWindowW && fy >= y0 && fy < y0 + kWindowH)
                    ++count;
            }
        }
        truth.push_back(count);
        distributed.push_back(top_part.sample(rng.next_double()) +
                              bottom_part.sample(rng.next_double()));
        const double mixed = shader::output_blend(
            static_cast<float>(top.sample(rng.next_double())),
            static_cast<float>(bottom.sample(rng.next_double())), static_cast<float>(w_top));
        blend.push_back(static_cast<int64_t>(std::floor(mixed + 0.5)));
        const int64_t trials = window_trials.sample(rng.next_double());
        uniform.push_back(per_trials[static_cast<size_t>(trials - window_trials.first())].sample(
            rng.next_double()));
    }
    r.chi2_p_truth = chi_square_p(truth, truth_law);
    r.chi2_p_distributed = chi_square_p(distributed, truth_law);
    r.chi2_p_output_blend = chi_square_p(blend, truth_law);
    r.chi2_p_uniform = chi_square_p(uniform, truth_law);
    r.variance_truth = sample_variance(truth);
    r.variance_distributed = sample_variance(distributed);
    r.variance_output_blend = sample_variance(blend);
    return r;
}

}  // namespace glintlab
