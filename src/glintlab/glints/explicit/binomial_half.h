// Exact Binomial(n, 1/2) variates for the top-down facet hierarchy of the
// explicit ground truth (facet_field.h): every split halves a cell, so every
// draw has p = 1/2. Exact means: the returned value has the binomial law up
// to the rounding of double arithmetic, never a normal approximation.
//  - n <= 256: the number of ones among n independent fair bits (popcount).
//  - n > 256: Hörmann's BTRS, "The generation of binomial random variates",
//    J. Statist. Comput. Simul. 46 (1993), an exact transformed-rejection
//    sampler with squeeze, valid for n p >= 10. The acceptance test is
//    written as differences of Stirling series (as in TensorFlow's
//    random_binomial_op), so that it keeps ~1e-7 absolute accuracy in the log
//    density even for n ~ 1e13 where lgamma differences would cancel.
#pragma once

#include <cstdint>

#include "glintlab/core/rng.h"

namespace glintlab::explicit_gt {

// One Binomial(n, 1/2) variate from `rng` (n >= 0).
int64_t sample_binomial_half(int64_t n, Pcg32& rng);

}  // namespace glintlab::explicit_gt
