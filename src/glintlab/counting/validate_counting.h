// `glintlab validate counting`: statistical and numerical validation of the
// counting laws. The CLI prints report.to_text() or
// report.to_json().dump(2) and exits 0 iff report.passed().
// Contract and check domains: docs/VALIDATION.md, section "counting".
#pragma once

#include <cstdint>

#include "glintlab/validate/report.h"

namespace glintlab {

struct CountingValidationOptions {
    uint64_t seed = 1;
    int samples_per_cell = 100000;         // per (law, N, p) cell of the grid
    int fig4_samples = 100000;             // per law of the 000 Fig. 4 experiment
    double fig4_p = 0.3;                   // success probability of that experiment
    int pow_grid = 256;                    // points per axis of the 003 Fig. 5 domain
    int64_t robustness_samples = 1000000;  // random (N, p, xi) of the NaN sweep
};

ValidationReport validate_counting(const CountingValidationOptions& options);

}  // namespace glintlab
