// The fp32 accuracy of (1 - p)^N, naive and stable (003 Eq. 24-25, Fig. 5),
// over p in [1e-16, 1] and N in [1, 1e16] on a log-spaced grid.
#pragma once

namespace glintlab {

struct PowAccuracy {
    int grid = 0;  // points per axis
    // Largest relative error where the true value is >= 1e-6 (003 Fig. 5 is
    // plotted in absolute error; relative error is the stricter measure).
    double naive_rel_err_max = 0.0;
    double stable_rel_err_max = 0.0;
    // Largest absolute error over the whole domain (what 003 Fig. 5 plots).
    double naive_abs_err_max = 0.0;
    double stable_abs_err_max = 0.0;
    // Where the naive form is worst (a witness for the report).
    double naive_worst_p = 0.0;
    double naive_worst_N = 0.0;
};

// The reference is exp(N log1p(-p)) in double for the fp32-rounded (N, p).
PowAccuracy measure_pow_accuracy(int grid);

}  // namespace glintlab
