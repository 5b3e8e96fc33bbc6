// Measurements of the deliot2023 model's properties (docs/VALIDATION.md,
// section "deliot2023"), shared by `glintlab validate deliot2023` and the tests.
#pragma once

#include <cstdint>
#include <vector>

#include "glintlab/glints/deliot2023/deliot2023.h"

namespace glintlab {

// 000 Eq. 5-6, Fig. 13: mean of D_P(h) over random footprints (random uv,
// orientation, anisotropy up to 8) at a density so high that every footprint
// holds ~1e7 facets, relative to the smooth D(h).
struct ConvergenceCase {
    int ndf;
    float alpha;
    float tan_theta;  // slope of h
    double mean_dp = 0.0;
    double target = 0.0;
    double rel_err = 0.0;
};
std::vector<ConvergenceCase> deliot2023_convergence(int footprints_per_case, uint64_t seed,
                                                    bool original_defects);

// 000 §4, Fig. 4: footprint sizes sweeping across one LOD boundary (LOD from
// l - 0.5 to l + 0.5). Per step: mean of D_P / D(h) (1 if the expected count
// is preserved) and the variance of the blended count relative to the
// binomial variance of the footprint's trials (000 Fig. 4c).
struct LodTransitionStep {
    double lod = 0.0;
    double mean_ratio = 0.0;            // mean(D_P) / D(h)
    double mean_trials = 0.0;           // mean blended trial count T of the footprint
    double count_variance_ratio = 0.0;  // Var(C) / (E[T] p (1 - p))
};
std::vector<LodTransitionStep> deliot2023_lod_transition(int steps, int footprints_per_step,
                                                         uint64_t seed);

// Random evaluations over the whole input domain (h incl. below the horizon
// and grazing; footprints zero, collinear, tiny, huge, grazing; uv far from
// the origin; parameters at their range edges); counts results that are not
// finite or negative.
struct RobustnessResult {
    int64_t evaluations = 0;
    int64_t bad_fixed = 0;     // fixed model
    int64_t bad_original = 0;  // original_defects = true
};
RobustnessResult deliot2023_robustness(int64_t evaluations, uint64_t seed);

// Determinism and temporal coherence: the same inputs evaluated twice, uv
// moved by `uv_step` x minor footprint width, and the footprint scaled by
// (1 + footprint_step).
struct CoherenceResult {
    int64_t mismatches = 0;                // bitwise differences on re-evaluation
    double uv_max_rel_change = 0.0;        // max |dD_P| / (D_P(x) + D_P(x') + D(h))
    double footprint_jump_fraction = 0.0;  // fraction of changes above 10 % (same norm)
};
CoherenceResult deliot2023_coherence(int pairs, double uv_step, double footprint_step,
                                     uint64_t seed);

}  // namespace glintlab
