// Bloom: the glare around very bright pixels (glints, the sun) that a real
// lens and eye add, applied to linear HDR images before tonemapping.
#pragma once

#include "glintlab/core/image.h"

namespace glintlab {

struct BloomSettings {
    float strength = 0.0f;   // fraction of the bright energy that is spread; 0 = off, valid [0, 1]
    float radius_px = 8.0f;  // kernel scale in pixels (see bloom_blur.h), valid > 0
    float threshold = 1.0f;  // luminance above which energy blooms, valid >= 0
};

// Throws glintlab::Error naming the parameter and its allowed range.
void validate(const BloomSettings& settings);

// The part of each pixel whose luminance exceeds the threshold: the pixel
// scaled by max(0, Y - threshold) / Y, which keeps its hue and leaves a
// remainder of luminance min(Y, threshold).
Image extract_bright(const Image& image, float threshold);

// out = image - strength * bright + strength * bloom_blur(bright).
// Energy-conserving: the sum of each channel is unchanged (bloom_blur keeps
// energy inside the frame). Returns the input unchanged when strength is 0.
Image apply_bloom(const Image& image, const BloomSettings& settings);

}  // namespace glintlab
