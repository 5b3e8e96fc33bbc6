#include "glintlab/glints/explicit/count_chi2.h"

#include <fmt/format.h>
#include <algorithm>
#include <boost/math/special_functions/gamma.hpp>

#include "glintlab/counting/exact_binomial.h"

namespace glintlab::explicit_gt {

std::string CountChi2::describe() const {
    return fmt::format("chi2 = {:.1f}, dof = {}, p = {:.3g}, mean {:.3f} (expected {:.3f})",
                       statistic, dof, p_value, mean, expected_mean);
}

CountChi2 count_chi2(const std::vector<int64_t>& counts, double N, double p) {
    const BinomialReference law(N, p);
    const double m = static_cast<double>(counts.size());
    CountChi2 r;
    r.expected_mean = N * p;
    for (int64_t c : counts) r.mean += double(c) / m;
    // Bins [lo_k, hi_k] with expected >= 5, tails included in the first and last.
    const int64_t first = law.first(), last = law.last();
    std::vector<double> expected, observed;
    std::vector<int64_t> upper;  // inclusive upper count of each bin
    double acc = 0.0;
    for (int64_t k = first; k <= last; ++k) {
        acc += law.pmf(k) * m;
        if (acc >= 5.0) {
            expected.push_back(acc);
            upper.push_back(k);
            acc = 0.0;
        }
    }
    if (expected.empty()) {
        expected.push_back(acc);
        upper.push_back(last);
    } else {
        expected.back() += acc;  // the remainder joins the last bin
        upper.back() = last;
    }
    observed.assign(expected.size(), 0.0);
    for (int64_t c : counts) {
        const auto it = std::lower_bound(upper.begin(), upper.end(), c);
        const size_t i = it == upper.end() ? upper.size() - 1 : size_t(it - upper.begin());
        observed[i] += 1.0;  // counts below `first` fall in bin 0 (mass < 1e-20)
    }
    for (size_t i = 0; i < expected.size(); ++i) {
        const double d = observed[i] - expected[i];
        r.statistic += d * d / expected[i];
    }
    r.dof = int(expected.size()) - 1;
    r.p_value = r.dof > 0 ? boost::math::gamma_q(0.5 * r.dof, 0.5 * r.statistic) : 1.0;
    return r;
}

}  // namespace glintlab::explicit_gt
