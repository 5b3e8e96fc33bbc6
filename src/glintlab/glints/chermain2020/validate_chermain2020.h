// `glintlab validate chermain2020`: convergence to Beckmann, weak white
// furnace (004 Eq. 17), reciprocity and robustness of the chermain2020 model.
// Checks and their domains: docs/VALIDATION.md, section "chermain2020".
#pragma once

#include <cstdint>

#include "glintlab/validate/report.h"

namespace glintlab {

struct Chermain2020ValidationOptions {
    uint64_t seed = 1;
    int convergence_footprints = 2000;  // per (alpha, h) case
    int reciprocity_pairs = 100000;
    int64_t robustness_evaluations = 10000000;
};

ValidationReport validate_chermain2020(const Chermain2020ValidationOptions& options);

}  // namespace glintlab
