// Robustness sweep of the shared counting laws: random (N, p, xi) including
// the edges N = 0, p = 0, p = 1, p < 1e-30 and N > 1e15; counts every NaN,
// Inf or negative output of every fp32 law (and of the multinomial).
#pragma once

#include <cstdint>

namespace glintlab {

struct RobustnessResult {
    int64_t evaluations = 0;  // law evaluations made
    int64_t invalid = 0;      // NaN, Inf or negative outputs among them
};

// `samples` random parameter sets, each fed to every law; deterministic for a
// seed whatever the number of threads (fixed chunks with their own streams).
RobustnessResult sweep_counting_laws(int64_t samples, uint64_t seed);

}  // namespace glintlab
