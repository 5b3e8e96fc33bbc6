// Metrics comparing a GPU image with the CPU `direct` image of the same view
// (docs/VALIDATION.md "CPU vs GPU"). Glints are sparse, bright and decided by
// fp32 thresholds, so a per-pixel RMSE is dominated by a few flipped glints;
// the metrics separate the energy (means, smoothed images) from the pixel
// pattern (fraction of mismatching pixels).
#pragma once

#include "glintlab/core/image.h"

namespace glintlab {

struct ImageAgreement {
    double mean_a = 0.0, mean_b = 0.0;  // mean luminance
    double mean_relative_error = 0.0;   // |mean_a - mean_b| / mean_b
    double smoothed_relative_l1 = 0.0;  // sum |A - B| / sum |B| over block means
    double mismatch_fraction = 0.0;     // pixels whose luminances differ beyond the tolerance
};

// `block`: side of the square blocks averaged for the smoothed metric.
// A pixel mismatches when |a - b| > abs_tol + rel_tol * max(a, b) (luminance).
// Throws glintlab::Error when the sizes differ.
ImageAgreement compare_images(const Image& a, const Image& b, int block, float abs_tol,
                              float rel_tol);

}  // namespace glintlab
