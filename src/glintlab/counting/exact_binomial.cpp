#include "glintlab/counting/exact_binomial.h"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/binomial.hpp>

#include "glintlab/core/error.h"

namespace glintlab {

BinomialReference::BinomialReference(double N, double p) : N_(N), p_(p) {
    if (!(N >= 0.0 && N <= 9007199254740992.0))
        fail("counting reference: N = {} outside the allowed range [0, 2^53]", N);
    if (!(p >= 0.0 && p <= 1.0))
        fail("counting reference: p = {} outside the allowed range [0, 1]", p);
    const double n0 = std::floor(N);
    const double lambda = N - n0;
    const double q = 1.0 - p;
    // Mixture variance: E[X^2] - (N p)^2 with E[X^2] = n p q + (n p)^2 per component.
    const auto second_moment = [&](double n) { return n * p * q + n * n * p * p; };
    variance_ = std::max(0.0, (1.0 - lambda) * second_moment(n0) +
                                  lambda * second_moment(n0 + 1.0) - mean() * mean());
    // Window mean +- (12 sigma + 12): beyond it the Chernoff bound of either
    // component is below 1e-20 for every (N, p) (Gaussian tail exp(-72) for
    // large variance, Poisson-like tail mean^k/k! < 1e-20 for small mean).
    const double sigma = std::sqrt(variance_);
    const double n_max = lambda > 0.0 ? n0 + 1.0 : n0;
    const double lo = std::max(0.0, std::floor(mean() - 12.0 * sigma - 12.0));
    const double hi = std::min(n_max, std::ceil(mean() + 12.0 * sigma + 12.0));
    first_ = static_cast<int64_t>(lo);
    const auto count = static_cast<size_t>(hi - lo) + 1;
    pmf_.assign(count, 0.0);
    const auto add_component = [&](double n, double weight) {
        if (weight <= 0.0) return;
        if (n == 0.0 || p == 0.0) {
            pmf_[static_cast<size_t>(0 - first_)] += weight;  // all mass at 0 (first_ is 0)
            return;
        }
        if (p == 1.0) {
            if (n >= lo && n <= hi) pmf_[static_cast<size_t>(n - lo)] += weight;
            return;
        }
        const boost::math::binomial_distribution<double> law(n, p);
        const double top = std::min(n, hi);
        for (double k = lo; k <= top; k += 1.0)
            pmf_[static_cast<size_t>(k - lo)] += weight * boost::math::pdf(law, k);
    };
    add_component(n0, 1.0 - lambda);
    add_component(n0 + 1.0, lambda);
    cdf_.resize(count);
    double acc = 0.0;
    for (size_t i = 0; i < count; ++i) cdf_[i] = (acc += pmf_[i]);
}

double BinomialReference::pmf(int64_t k) const {
    if (k < first() || k > last()) return 0.0;
    return pmf_[static_cast<size_t>(k - first_)];
}

int64_t BinomialReference::sample(double u) const {
    // The table's total differs from 1 by the dropped tails (< 1e-20) and
    // rounding; scaling u by it keeps the inversion inside the table.
    const double target = u * cdf_.back();
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), target);
    const auto index =
        std::min<ptrdiff_t>(it - cdf_.begin(), static_cast<ptrdiff_t>(cdf_.size()) - 1);
    return first_ + index;
}

}  // namespace glintlab
