// `glintlab validate jakob2014`: count statistics against the binomial law,
// convergence of D_P to the smooth NDF, the 002 Table 1 query statistics and
// robustness. Checks and their domains: docs/VALIDATION.md, "jakob2014".
#pragma once

#include <cstdint>

#include "glintlab/validate/report.h"

namespace glintlab {

struct Jakob2014ValidationOptions {
    uint64_t seed = 1;
    int count_footprints = 3000;        // per query geometry
    int convergence_footprints = 400;   // per case
    double convergence_count = 1000.0;  // expected particles per query (>= 1e3)
    int table1_pixels = 20000;          // queries per Table 1 setting
    int robustness_queries = 4000;
    int explicit_pixels = 128;         // footprints per side of the explicit comparison
    int explicit_realizations = 16;    // particle sets (seeds) per model
    int environment_pixels = 24;       // footprints per side under the environment
    int environment_realizations = 4;  // seeds per model under the environment
    int environment_samples = 256;     // jakob2014 MC samples per estimate (2 per pixel)
};

ValidationReport validate_jakob2014(const Jakob2014ValidationOptions& options);

}  // namespace glintlab
