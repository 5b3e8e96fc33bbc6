// `glintlab validate zirr2016`: convergence (measured over a density sweep),
// LOD-blend count statistics and robustness of the zirr2016 baseline.
// Checks and their domains: docs/VALIDATION.md, section "zirr2016".
#pragma once

#include <cstdint>

#include "glintlab/validate/report.h"

namespace glintlab {

struct Zirr2016ValidationOptions {
    uint64_t seed = 1;
    int convergence_footprints = 400;  // per (NDF, alpha, h, density) case
    int lod_steps = 9;                 // LODs across one level
    int lod_footprints = 4000;         // per LOD
    int64_t robustness_evaluations = 10000000;
};

ValidationReport validate_zirr2016(const Zirr2016ValidationOptions& options);

}  // namespace glintlab
