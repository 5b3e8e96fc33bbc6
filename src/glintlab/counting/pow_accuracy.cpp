#include "glintlab/counting/pow_accuracy.h"

#include <algorithm>
#include <cmath>

#include "glintlab/counting/laws.h"

namespace glintlab {

PowAccuracy measure_pow_accuracy(int grid) {
    PowAccuracy r;
    r.grid = std::max(grid, 2);
    for (int i = 0; i < r.grid; ++i) {
        const auto p = static_cast<float>(std::pow(10.0, -16.0 + 16.0 * i / (r.grid - 1)));
        for (int j = 0; j < r.grid; ++j) {
            const auto N = static_cast<float>(std::pow(10.0, 16.0 * j / (r.grid - 1)));
            const double truth =
                std::exp(static_cast<double>(N) * std::log1p(-static_cast<double>(p)));
            const double naive = shader::pow_one_minus_naive(p, N);
            const double stable = shader::pow_one_minus_stable(p, N);
            const double naive_abs = std::abs(naive - truth);
            const double stable_abs = std::abs(stable - truth);
            r.stable_abs_err_max = std::max(r.stable_abs_err_max, stable_abs);
            if (naive_abs > r.naive_abs_err_max) {
                r.naive_abs_err_max = naive_abs;
                r.naive_worst_p = p;
                r.naive_worst_N = N;
            }
            if (truth >= 1e-6) {
                r.naive_rel_err_max = std::max(r.naive_rel_err_max, naive_abs / truth);
                r.stable_rel_err_max = std::max(r.stable_rel_err_max, stable_abs / truth);
            }
        }
    }
    return r;
}

}  // namespace glintlab
