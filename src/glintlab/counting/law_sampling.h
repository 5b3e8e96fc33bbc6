// The counting laws as one C++ entry point, for the validation, the tests and
// the benchmarks: which laws exist, their names, and one sample of each.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "glintlab/core/rng.h"
#include "glintlab/counting/exact_binomial.h"

namespace glintlab {

enum class CountingLaw {
    exact,                     // inversion of the exact (mixture) law, exact_binomial.h
    gaussian,                  // binomial_gaussian
    zirr2016,                  // binomial_zirr2016 (000 Eq. 15)
    deliot2023,                // binomial_deliot2023 (000 Eq. 16-18)
    single_gated,              // binomial_single_gated (003 Eq. 23)
    dual_gated,                // binomial_dual_gated (003 Algorithm 1), positives
    single_gated_conditional,  // binomial_single_gated_conditional (Law 5b, unbiased mean)
};

std::span<const CountingLaw> all_counting_laws();
std::string_view law_name(CountingLaw law);
// The constant-cost gated laws whose mean the validation checks.
bool is_gated(CountingLaw law);

// The uniforms of one sample: xi1 gates (or inverts the exact CDF), xi2 feeds
// the Gaussian; laws needing more (zirr2016's trials) draw them from `rng`.
struct LawUniforms {
    double xi1 = 0.0;
    double xi2 = 0.0;
};

// One sample of `law` for (N, p); `exact` must be the reference of (N, p) for
// CountingLaw::exact and is ignored otherwise. Real-valued where the law is.
double sample_count(CountingLaw law, double N, double p, const LawUniforms& xi, Pcg32& rng,
                    const BinomialReference* exact);

}  // namespace glintlab
