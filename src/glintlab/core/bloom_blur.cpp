#include "glintlab/core/bloom_blur.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>

namespace glintlab {
namespace {

// Normalised taps w[0..2R] for offsets -R..R.
std::vector<float> gaussian_taps(float sigma) {
    const int radius = std::max(1, int(std::ceil(4.0f * sigma)));
    std::vector<float> taps(size_t(2 * radius + 1));
    double sum = 0.0;
    for (int k = -radius; k <= radius; ++k) {
        const double w = std::exp(-0.5 * double(k) * double(k) / (double(sigma) * sigma));
        taps[size_t(k + radius)] = float(w);
        sum += w;
    }
    for (float& w : taps) w = float(double(w) / sum);
    return taps;
}

// 1 / (total weight a source at position i deposits inside [0, n)): scaling the source by it
// makes the gather below a conserving scatter. Equals 1 away from the borders.
std::vector<float> source_scales(const std::vector<float>& taps, int n) {
    const int radius = int(taps.size() / 2);
    std::vector<float> scale(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        double inside = 0.0;
        for (int k = -radius; k <= radius; ++k)
            if (i + k >= 0 && i + k < n) inside += taps[size_t(k + radius)];
        scale[size_t(i)] = float(1.0 / inside);
    }
    return scale;
}

bool row_is_zero(const Image& image, int y) {
    const glm::vec3* row = &image.pixels[size_t(y) * size_t(image.width)];
    return std::all_of(row, row + image.width, [](glm::vec3 p) { return p == glm::vec3(0.0f); });
}

std::vector<char> zero_rows(const Image& image) {
    std::vector<char> zero(size_t(image.height));
    tbb::parallel_for(0, image.height, [&](int y) { zero[size_t(y)] = row_is_zero(image, y); });
    return zero;
}

Image blur_rows(const Image& in, const std::vector<float>& taps) {
    const int radius = int(taps.size() / 2);
    const std::vector<float> scale = source_scales(taps, in.width);
    Image out(in.width, in.height);
    tbb::parallel_for(0, in.height, [&](int y) {
        if (row_is_zero(in, y)) return;  // bloom sources are sparse: most rows are empty
        // Scaled sources with `radius` zeros either side: the convolution below then needs
        // no bounds tests in its inner loop.
        std::vector<glm::vec3> padded(size_t(in.width + 2 * radius), glm::vec3(0.0f));
        for (int x = 0; x < in.width; ++x)
            padded[size_t(x + radius)] = scale[size_t(x)] * in.at(x, y);
        for (int x = 0; x < in.width; ++x) {
            glm::vec3 sum(0.0f);
            const glm::vec3* src = &padded[size_t(x)];  // src[j] is source x - radius + j
            for (size_t j = 0; j < taps.size(); ++j) sum += taps[taps.size() - 1 - j] * src[j];
            out.at(x, y) = sum;
        }
    });
    return out;
}

// Vertical pass organised by output rows so every inner loop walks memory contiguously.
Image blur_columns(const Image& in, const std::vector<float>& taps) {
    const int radius = int(taps.size() / 2);
    const std::vector<float> scale = source_scales(taps, in.height);
    const std::vector<char> zero = zero_rows(in);
    Image out(in.width, in.height);
    tbb::parallel_for(0, in.height, [&](int y) {
        glm::vec3* dst = &out.pixels[size_t(y) * size_t(in.width)];
        const int lo = std::max(-radius, y - in.height + 1), hi = std::min(radius, y);
        for (int k = lo; k <= hi; ++k) {
            if (zero[size_t(y - k)]) continue;
            const float w = taps[size_t(k + radius)] * scale[size_t(y - k)];
            const glm::vec3* src = &in.pixels[size_t(y - k) * size_t(in.width)];
            for (int x = 0; x < in.width; ++x) dst[x] += w * src[x];
        }
    });
    return out;
}

}  // namespace

Image gaussian_blur_conserving(const Image& image, float sigma_px) {
    const std::vector<float> taps = gaussian_taps(sigma_px);
    return blur_columns(blur_rows(image, taps), taps);
}

Image bloom_blur(const Image& image, float radius_px) {
    constexpr float kOctaveScales[] = {0.25f, 0.5f, 1.0f, 2.0f};
    constexpr float kWeight = 1.0f / 4.0f;
    Image sum(image.width, image.height);
    for (float octave : kOctaveScales) {
        const Image blurred = gaussian_blur_conserving(image, octave * radius_px);
        for (size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += kWeight * blurred.pixels[i];
    }
    return sum;
}

}  // namespace glintlab
