// Energy-conserving Gaussian blurs used by the bloom filter (bloom.h).
#pragma once

#include "glintlab/core/image.h"

namespace glintlab {

// Separable Gaussian blur of standard deviation sigma_px (> 0), truncated at
// 4 sigma. At the borders the kernel is renormalised per *source* pixel
// (scatter normalisation): every source pixel spreads all of its energy over
// the pixels inside the image, so the sum of each channel is preserved
// exactly (up to float rounding) and nothing leaves through the borders.
Image gaussian_blur_conserving(const Image& image, float sigma_px);

// The bloom kernel: the mean of four Gaussians with sigma = radius_px times
// 1/4, 1/2, 1 and 2 (one octave apart). A sum of octave-spaced Gaussians
// approximates the heavy-tailed, roughly 1/r falloff of veiling glare much
// better than a single Gaussian; it is the direct (full resolution) form of
// a mip-chain bloom, chosen because it makes exact conservation easy to test.
Image bloom_blur(const Image& image, float radius_px);

}  // namespace glintlab
