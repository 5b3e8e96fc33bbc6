// `glintlab validate explicit`: the ground truth's own statistics and
// radiometry. Checks (docs/VALIDATION.md, "explicit"):
//  - count_chi2_p_min: for fixed query geometries, the counts over many
//    independent fields (seeds) of the facets in the footprint, and of those
//    that also reflect wo into the γ cone around wi, against
//    Binomial(N, a(A)) and Binomial(N, a(A) p_dir) (p_dir by quadrature);
//    the smallest p-value times the number of tests (Bonferroni) > 0.001;
//  - convergence_rel_err_max: mean D_P over footprints with >= 1e3 expected
//    facets in the cone vs its exact expectation, and the environment
//    radiance vs the smooth BRDF's (quadrature): <= 0.01;
//  - nan_count: non-finite outputs over random and degenerate queries = 0.
#pragma once

#include <cstdint>

#include "glintlab/validate/report.h"

namespace glintlab {

struct ExplicitValidationOptions {
    uint64_t seed = 1;
    int count_footprints = 2000;        // independent fields per geometry
    double count_mean = 30.0;           // expected in-cone count of the count test
    int convergence_footprints = 160;   // per geometry
    double convergence_count = 1000.0;  // expected in-cone facets per query (>= 1e3)
    double environment_facets = 1.0e6;  // facets of the environment convergence
    int robustness_queries = 2000;
};

ValidationReport validate_explicit(const ExplicitValidationOptions& options);

}  // namespace glintlab
