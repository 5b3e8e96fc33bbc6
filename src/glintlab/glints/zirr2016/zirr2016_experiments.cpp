#include "glintlab/glints/zirr2016/zirr2016_experiments.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <tbb/parallel_for.h>

#include "glintlab/core/rng.h"
#include "glintlab/validate/random_queries.h"
#include "glintlab/validate/robustness_loop.h"

namespace glintlab {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kBeckmann = 0;  // shader::NDF_BECKMANN
constexpr int kGgx = 1;       // shader::NDF_GGX

}  // namespace

std::vector<Zirr2016ConvergenceCase> zirr2016_convergence(float log_density,
                                                          int footprints_per_case, uint64_t seed) {
    std::vector<Zirr2016ConvergenceCase> cases;
    for (int ndf : {kBeckmann, kGgx})
        for (float alpha : {0.1f, 0.3f, 0.7f})
            for (float t : {0.0f, 0.5f, 1.0f, 2.0f}) {
                Zirr2016ConvergenceCase c;
                c.ndf = ndf;
                c.alpha = alpha;
                c.tan_theta = t * alpha;
                c.log_density = log_density;
                cases.push_back(c);
            }
    const Zirr2016Params params;
    tbb::parallel_for(size_t{0}, cases.size(), [&](size_t i) {
        Zirr2016ConvergenceCase& k = cases[i];
        Zirr2016Target target;
        target.ndf = k.ndf;
        target.alpha_x = target.alpha_y = k.alpha;
        target.log_density = log_density;
        Pcg32 rng(i, seed);
        const glm::vec3 h = half_vector_at(k.tan_theta, 0.7);
        k.mean_dp = mean_over_random_footprints(rng, footprints_per_case,
                                                [&](const Footprint& fp, uint32_t seed) {
                                                    target.seed = seed;
                                                    return zirr2016_ndf(h, fp, target, params);
                                                });
        k.target = zirr2016_target_ndf(h, target);
        k.rel_err = std::abs(k.mean_dp / k.target - 1.0);
    });
    return cases;
}

Zirr2016CountStats zirr2016_count_stats(double lod, double bottom_trials, float R, int footprints,
                                        uint64_t seed) {
    // Bottom level l0 = floor(lod) holds `bottom_trials` per texel: ln density
    // = ln(bottom_trials) - 2 l0 ln 2. Isotropic footprint of minor width 2^lod (S = 1).
    const double l0 = std::floor(lod), w = lod - l0;
    Zirr2016Target target;
    target.log_density = static_cast<float>(std::log(bottom_trials) - 2.0 * l0 * std::log(2.0));
    Zirr2016Params params;
    params.microfacet_roughness = R;
    params.screen_space_scale = 1.0f;
    const double trials = (1.0 - w) * bottom_trials + w * 4.0 * bottom_trials;  // Eq. 7 mix of N(P)
    const double expected = trials * R;
    const double d_n = zirr2016_target_ndf(glm::vec3(0, 0, 1), target);
    Pcg32 rng(0, seed);
    double sum = 0.0, sum2 = 0.0;
    const double minor = std::exp2(lod);
    for (int f = 0; f < footprints; ++f) {
        target.seed = rng.next_uint();
        const glm::vec2 uv(rng.next_float() * 64.0f, rng.next_float() * 64.0f);
        const Footprint fp = oriented_footprint(uv, minor, 1.0, rng.next_double() * kPi);
        // h = normal: p = R D(n) / D(n) = R (Eq. 4), and the count is D_P R / D(n) x trials.
        const double c = zirr2016_ndf(glm::vec3(0, 0, 1), fp, target, params) * R / d_n * trials;
        sum += c;
        sum2 += c * c;
    }
    const double mean = sum / footprints;
    const double var = (sum2 - sum * mean) / (footprints - 1);
    Zirr2016CountStats s;
    s.lod = lod;
    s.mean_ratio = mean / expected;
    s.variance_over_mean = var / mean;
    return s;
}

Zirr2016RobustnessResult zirr2016_robustness(int64_t evaluations, uint64_t seed) {
    std::atomic<int64_t> bad{0};
    for_each_robustness_query(evaluations, seed,
                              [&](Pcg32& rng, int64_t, const RobustnessQuery& q) {
                                  const auto t = robustness_target<Zirr2016Target>(q);
                                  Zirr2016Params p;
                                  p.microfacet_roughness = draw_log_with_ends(rng, -4, 0);
                                  p.max_anisotropy = draw_with_ends(rng, 1.0f, 64.0f);
                                  p.screen_space_scale = draw_with_ends(rng, 0.5f, 8.0f);
                                  const float d = zirr2016_ndf(q.h, q.footprint, t, p);
                                  if (!std::isfinite(d) || d < 0.0f) ++bad;
                              });
    return {evaluations, bad.load()};
}

}  // namespace glintlab
