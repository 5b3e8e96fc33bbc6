// Numerical experiments on the zirr2016 model shared by its tests and by
// `glintlab validate zirr2016` (docs/VALIDATION.md, section "zirr2016").
#pragma once

#include <cstdint>
#include <vector>

#include "glintlab/glints/zirr2016/zirr2016.h"

namespace glintlab {

// Mean of D_P over random footprints (random uv, seed, ratio in [1, 8],
// orientation; minor width 1e-3 uv) against the smooth D(h).
struct Zirr2016ConvergenceCase {
    int ndf = 0;
    float alpha = 0.0f;
    float tan_theta = 0.0f;
    float log_density = 0.0f;
    double mean_dp = 0.0;
    double target = 0.0;
    double rel_err = 0.0;  // |mean_dp / target - 1|
};
// Beckmann and GGX x alpha {0.1, 0.3, 0.7} x tan(theta_h)/alpha {0, 0.5, 1, 2}.
std::vector<Zirr2016ConvergenceCase> zirr2016_convergence(float log_density,
                                                          int footprints_per_case, uint64_t seed);

// Statistics of the count C = D_P R / D(n) x trials of isotropic footprints
// whose LOD is `lod` (h = normal, so p = R): mean over the expected count
// N(P) p and Var(C) / mean (1 for a true binomial with small p).
struct Zirr2016CountStats {
    double lod = 0.0;
    double mean_ratio = 0.0;          // E[C] / (trials p)
    double variance_over_mean = 0.0;  // Var(C) / E[C]
};
Zirr2016CountStats zirr2016_count_stats(double lod, double bottom_trials, float R, int footprints,
                                        uint64_t seed);

// Evaluations over extreme inputs (h anywhere on the sphere, degenerate and
// huge footprints, any density/roughness/anisotropy): how many were NaN, Inf
// or negative.
struct Zirr2016RobustnessResult {
    int64_t evaluations = 0;
    int64_t bad = 0;
};
Zirr2016RobustnessResult zirr2016_robustness(int64_t evaluations, uint64_t seed);

}  // namespace glintlab
