// `glintlab validate robustness`: every glint model's footprint NDF and BRDF
// (and, for the models that shade lights themselves, light_radiance under a
// constant environment of radiance up to 10^6, a sun cone, a sphere light and
// a point light as the model supports) evaluated at random in-range
// parameters: roughness bounds, log density over the model's range with both
// ends drawn exactly, each parameter block's extremes, directions down to
// grazing (cos 1e-7) and below the horizon, footprints from zero and 1e-20
// to the model's largest. Counts NaN, Inf and negative values per model; the
// checks require 0 per model (docs/VALIDATION.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "glintlab/validate/report.h"

namespace glintlab {

struct RobustnessSuiteOptions {
    uint64_t seed = 1;
    // Total evaluations over all models (shared out by each model's weight,
    // docs/VALIDATION.md); the test suite runs ~1e5.
    int64_t evaluations = 10'000'000;
    // Empty: every model. Each model gets the evaluations it gets in the full
    // suite (its share of `evaluations` by weight, whatever else is chosen),
    // with the same draws, so per-model runs add up to the full one.
    // An unknown name is an error listing the models.
    std::vector<std::string> models;
    // The test suite's version: models that build tables per material
    // (wang2020) sweep only their material whose tables build in seconds
    // (roughness 1, log density 0; roughness 0.02 takes ~1.5 min).
    bool reduced = false;
};

struct RobustnessModelResult {
    std::string model;
    int64_t evaluations = 0;    // values checked (NDF, BRDF, light radiance; one per call)
    int64_t bad_values = 0;     // NaN, Inf or negative among them
    int64_t refused = 0;        // calls the model refused with glintlab::Error (a clear message)
    std::string first_bad;      // the inputs of the first bad value, for the report
    std::string first_refusal;  // the first refusal's message
    double seconds = 0.0;       // wall time of the model's sweep (tables included)
};

std::vector<RobustnessModelResult> run_robustness(const RobustnessSuiteOptions& options);
ValidationReport validate_robustness(const RobustnessSuiteOptions& options);
// The full suite (10^7 values) with a seed: `glintlab validate robustness`.
ValidationReport validate_robustness(uint64_t seed);

}  // namespace glintlab
