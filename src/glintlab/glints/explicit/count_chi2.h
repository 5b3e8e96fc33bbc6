// Pearson chi-square test of observed integer counts against Binomial(N, p)
// (the law of the facet count of a fixed query region, explicit.h), used by
// the tests and by `glintlab validate explicit`. Bins are single counts from
// the exact pmf (counting/exact_binomial.h); neighbouring bins are pooled
// until each expects >= 5 samples, the two tails are open-ended bins.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace glintlab::explicit_gt {

struct CountChi2 {
    double statistic = 0.0;
    int dof = 0;
    double p_value = 1.0;
    double mean = 0.0, expected_mean = 0.0;
    std::string describe() const;
};

CountChi2 count_chi2(const std::vector<int64_t>& counts, double N, double p);

}  // namespace glintlab::explicit_gt
