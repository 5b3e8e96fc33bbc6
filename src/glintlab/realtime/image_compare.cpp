#include "glintlab/realtime/image_compare.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "glintlab/core/error.h"

namespace glintlab {

ImageAgreement compare_images(const Image& a, const Image& b, int block, float abs_tol,
                              float rel_tol) {
    if (a.width != b.width || a.height != b.height)
        fail("compare_images: sizes differ ({}x{} vs {}x{})", a.width, a.height, b.width, b.height);
    if (block < 1) fail("compare_images: block must be >= 1, got {}", block);
    ImageAgreement r;
    const size_t n = a.pixels.size();
    if (n == 0) return r;
    size_t mismatches = 0;
    const int bw = (a.width + block - 1) / block, bh = (a.height + block - 1) / block;
    std::vector<double> block_a(static_cast<size_t>(bw) * bh, 0.0), block_b(block_a.size(), 0.0);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const double la = luminance(a.at(x, y)), lb = luminance(b.at(x, y));
            r.mean_a += la;
            r.mean_b += lb;
            const size_t k = static_cast<size_t>(y / block) * bw + static_cast<size_t>(x / block);
            block_a[k] += la;
            block_b[k] += lb;
            if (std::abs(la - lb) > abs_tol + rel_tol * std::max(la, lb)) ++mismatches;
        }
    r.mean_a /= static_cast<double>(n);
    r.mean_b /= static_cast<double>(n);
    r.mean_relative_error =
        r.mean_b > 0.0 ? std::abs(r.mean_a - r.mean_b) / r.mean_b : (r.mean_a > 0.0 ? 1.0 : 0.0);
    double diff = 0.0, sum = 0.0;
    for (size_t k = 0; k < block_a.size(); ++k) {
        diff += std::abs(block_a[k] - block_b[k]);
        sum += std::abs(block_b[k]);
    }
    r.smoothed_relative_l1 = sum > 0.0 ? diff / sum : (diff > 0.0 ? 1.0 : 0.0);
    r.mismatch_fraction = static_cast<double>(mismatches) / static_cast<double>(n);
    return r;
}

}  // namespace glintlab
