// The exact reference law of the counting validation: the binomial law
// b(N, p) for integer N and, for real N >= 0, the mixture of the two
// neighbouring integer laws (003 §6 and Fig. 4):
//     (1 - lambda) Bin(floor N, p) + lambda Bin(floor N + 1, p),  lambda = N - floor N,
// whose mean is exactly N p. Probabilities come from Boost.Math.
#pragma once

#include <cstdint>
#include <vector>

namespace glintlab {

class BinomialReference {
  public:
    // N >= 0 (up to 2^53), p in [0, 1]; throws glintlab::Error otherwise.
    BinomialReference(double N, double p);

    double trials() const { return N_; }
    double probability() const { return p_; }
    double mean() const { return N_ * p_; }
    double variance() const { return variance_; }

    // The table covers counts [first(), last()]; the mass left outside it is
    // below 1e-20 (mean +- 12 sigma + 12 counts, see the .cpp).
    int64_t first() const { return first_; }
    int64_t last() const { return first_ + static_cast<int64_t>(pmf_.size()) - 1; }
    double pmf(int64_t k) const;

    // Exact sampling by inversion of the tabulated CDF: u uniform in [0, 1).
    int64_t sample(double u) const;

  private:
    double N_;
    double p_;
    double variance_ = 0.0;
    int64_t first_ = 0;
    std::vector<double> pmf_;
    std::vector<double> cdf_;
};

}  // namespace glintlab
