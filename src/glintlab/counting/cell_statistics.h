// Statistics of one counting law on one (N, p) cell against the exact law:
// sample mean and variance, total-variation distance over integer bins, and a
// count of invalid outputs.
#pragma once

#include <cstdint>

#include "glintlab/counting/exact_binomial.h"
#include "glintlab/counting/law_sampling.h"

namespace glintlab {

struct CellStatistics {
    double N = 0.0;
    double p = 0.0;
    double mean = 0.0;
    double variance = 0.0;
    double ref_mean = 0.0;
    double ref_variance = 0.0;
    // Total variation over bins of width `bin_width` integers (1 while the
    // reference standard deviation is <= 5, see the .cpp).
    double tv = 0.0;
    int64_t bin_width = 1;
    int64_t invalid = 0;  // NaN, Inf or negative outputs
};

// Draws `samples` counts of `law` with Latin-hypercube stratified (xi1, xi2)
// from the stream `seed` (independent of threads), outputs rounded to the
// nearest integer for the histogram. `reference` is the exact law of (N, p).
CellStatistics measure_cell(CountingLaw law, const BinomialReference& reference, int samples,
                            uint64_t seed);

}  // namespace glintlab
