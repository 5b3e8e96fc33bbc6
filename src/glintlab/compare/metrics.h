// Pixel-level metrics of `glintlab compare` (docs/VALIDATION.md "compare"):
// one model's images against the explicit ground truth's. Every image here is
// a luminance plane (row-major, width x height) and every statistic is taken
// over the pixels of a mask (the pixels whose camera ray hits the compared
// material), so the background and other materials, identical in both
// renders, do not dilute an error.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "glintlab/core/image.h"

namespace glintlab::compare {

struct Plane {
    int width = 0, height = 0;
    std::vector<float> values;  // row-major

    Plane() = default;
    Plane(int w, int h, float fill = 0.0f)
        : width(w), height(h), values(size_t(w) * size_t(h), fill) {}
};

using Mask = std::vector<uint8_t>;  // 1: the pixel counts; size width * height

// Non-finite and negative pixels of an RGB image (a pixel counts once per
// class when any of its components is NaN / infinite / negative).
struct PixelFaults {
    int64_t nan = 0, inf = 0, negative = 0;
    int64_t total() const { return nan + inf + negative; }
    PixelFaults& operator+=(const PixelFaults& o) {
        nan += o.nan, inf += o.inf, negative += o.negative;
        return *this;
    }
};
PixelFaults count_pixel_faults(const Image& image);

// Luminance (core/image.h) of each pixel; non-finite pixels become 0 (they
// are counted by count_pixel_faults, and must not poison every statistic).
Plane luminance_plane(const Image& image);

// Mean over the mask's pixels (0 when the mask is empty).
double masked_mean(const Plane& plane, const Mask& mask);

// Relative error of one model's image mean against the ground truth's, each
// measured on R realizations (independent seeds): (mean(m) - mean(g)) /
// mean(g), and its standard error sqrt(s_m^2/R_m + s_g^2/R_g) / mean(g) with
// the sample variances of the per-realization means (0 with one realization).
struct MeanError {
    double relative_error = 0.0;
    double standard_error = 0.0;
};
MeanError mean_relative_error(const std::vector<double>& model_means,
                              const std::vector<double>& truth_means);

// Gaussian blur, separable, truncated at 3 sigma, clamped to the border;
// sigma <= 0 copies.
Plane gaussian_blur(const Plane& plane, double sigma_px);

// Root mean square of blur(model) - blur(truth) over the mask, divided by the
// mask mean of blur(truth): the error of the smooth component once the
// sparkle is averaged away.
double blurred_relative_rmse(const Plane& model, const Plane& truth, const Mask& mask,
                             double sigma_px);

// The blur that removes the sparkle: sigma = max(1.5, min(W, H) / 32) pixels.
// Sparkles are one-pixel features; a Gaussian of sigma s averages about
// 4 pi s^2 pixels (>= 28), dividing their standard deviation by >= 5, while
// the shading of an object filling the frame varies over ~W/2 pixels, which
// a kernel of W/32 barely softens.
double sparkle_blur_sigma(int width, int height);

// Mean over the mask of the per-pixel variance over realizations (sample
// variance, R - 1 in the denominator; needs R >= 2).
double mean_pixel_variance(const std::vector<Plane>& realizations, const Mask& mask);

// 1-Wasserstein distance between the empirical distributions of two samples
// (any sizes): the integral of |F_a - F_b|, computed exactly from the sorted
// samples. 0 for equal samples, |c| for a sample shifted by c.
double wasserstein1(std::vector<float> a, std::vector<float> b);

// The masked pixels of every realization, pooled (the per-pixel luminance
// distribution of a model).
std::vector<float> pooled_masked_values(const std::vector<Plane>& realizations, const Mask& mask);

// The per-pixel variance of one render's sampling noise, from two renders of
// the same microstructure and camera with independent sampling seeds a and
// b: the mean over the mask of (a - b)^2 / 2 (E[(a - b)^2] = 2 Var for
// independent draws of equal variance). mean_pixel_variance over
// realizations that each draw their own microstructure and sampling seed is
// the microstructure's variance plus this one, so their difference is the
// glint statistic without the estimator's noise.
double sampling_pixel_variance(const Plane& a, const Plane& b, const Mask& mask);

// Sample mean and variance of x (n - 1 in the denominator; variance 0 for
// one value, both 0 for none).
std::pair<double, double> sample_mean_variance(const std::vector<double>& x);

// Sample mean of x and its standard error (sample sd / sqrt(n); 0 for fewer
// than two values).
struct MeanEstimate {
    double mean = 0.0;
    double standard_error = 0.0;
};
MeanEstimate mean_with_standard_error(const std::vector<double>& x);

// Temporal flicker of a frame sequence: the mean over consecutive pairs of
// mean_p |L_{t+1}(p) - L_t(p)| / mean_p (L_t(p) + L_{t+1}(p)) / 2, over the
// pixels in both frames' masks. 0 for a frozen sequence.
double flicker(const std::vector<Plane>& frames, const std::vector<Mask>& masks);

// The flicker of several camera paths, each the same frames rendered with
// another realization (microstructure and sampling seed): the mean of the
// paths' flicker values and its standard error (their sample standard
// deviation / sqrt(paths); 0 for one path). One path is not enough where
// the sparkle is sparse: a few facets that reflect a bright source carry
// most of a frame's change, so the flicker of one realization varies by
// 2-3x between seeds (docs/VALIDATION.md "compare", flicker paths).
using FlickerEstimate = MeanEstimate;
FlickerEstimate flicker_over_paths(const std::vector<std::vector<Plane>>& paths,
                                   const std::vector<Mask>& masks);

// Per-pixel average of planes of equal size.
Plane average(const std::vector<Plane>& planes);

}  // namespace glintlab::compare
