#include "glintlab/core/bloom.h"

#include <cmath>

#include "glintlab/core/bloom_blur.h"
#include "glintlab/core/error.h"

namespace glintlab {

void validate(const BloomSettings& s) {
    // Written so that NaN fails every check.
    if (!(s.strength >= 0.0f && s.strength <= 1.0f))
        fail("bloom strength = {} is out of range (allowed: [0, 1], 0 = off)", s.strength);
    if (!(s.radius_px > 0.0f && std::isfinite(s.radius_px)))
        fail("bloom radius_px = {} is out of range (allowed: finite and > 0 pixels)", s.radius_px);
    if (!(s.threshold >= 0.0f && std::isfinite(s.threshold)))
        fail("bloom threshold = {} is out of range (allowed: finite and >= 0)", s.threshold);
}

Image extract_bright(const Image& image, float threshold) {
    Image bright(image.width, image.height);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const float y = luminance(image.pixels[i]);
        if (y > threshold) bright.pixels[i] = image.pixels[i] * ((y - threshold) / y);
    }
    return bright;
}

Image apply_bloom(const Image& image, const BloomSettings& settings) {
    validate(settings);
    if (settings.strength == 0.0f) return image;
    const Image bright = extract_bright(image, settings.threshold);
    const Image glow = bloom_blur(bright, settings.radius_px);
    Image out = image;
    for (size_t i = 0; i < out.pixels.size(); ++i)
        out.pixels[i] += settings.strength * (glow.pixels[i] - bright.pixels[i]);
    return out;
}

}  // namespace glintlab
