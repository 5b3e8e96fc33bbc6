// `glintlab validate deliot2023`: convergence, LOD transitions, robustness and
// coherence of the deliot2023 model. Checks and their domains:
// docs/VALIDATION.md, section "deliot2023".
#pragma once

#include <cstdint>

#include "glintlab/validate/report.h"

namespace glintlab {

struct Deliot2023ValidationOptions {
    uint64_t seed = 1;
    int convergence_footprints = 400;  // per (NDF, alpha, h) case
    int lod_steps = 21;                // footprint sizes across one LOD boundary
    int lod_footprints = 2000;         // per step
    int64_t robustness_evaluations = 10000000;
    int coherence_pairs = 20000;
};

ValidationReport validate_deliot2023(const Deliot2023ValidationOptions& options);

}  // namespace glintlab
