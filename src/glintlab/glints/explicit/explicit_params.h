// Parameters of the explicit ground-truth model (its block "explicit": {...}
// of a glint material; ranges justified in docs/MODELS.md, section explicit).
#pragma once

namespace glintlab {

struct ExplicitParams {
    // Half-angle γ of the query cone that delta lights (point, delta
    // directional) are spread over (002 §3.1: "a constant γ between 0.5 and 6
    // degrees in our scenes"), degrees.
    float gamma_deg = 1.0f;
    // Expected facets per pixel footprint above which shading fails with an
    // error instead of enumerating for minutes (docs/BENCHMARKS.md: ~48 ns
    // per facet, so 1e6 facets ~ 48 ms per shading call).
    double max_facets_per_footprint = 1e6;
    // "over_budget": what a footprint above that budget does. "error"
    // (default): shading fails, naming the footprint. "subsample": one of
    // K x K equal parts of the footprint is enumerated (K the smallest that
    // fits the budget), chosen by a hash of the footprint's centre; the
    // estimate, normalised by that part's expected count, stays unbiased
    // (docs/MODELS.md explicit). For the grazing and silhouette footprints
    // of ray differentials, e.g. in `glintlab compare`'s truth.
    bool subsample_over_budget = false;
};

}  // namespace glintlab
