#include "glintlab/compare/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "glintlab/core/error.h"

namespace glintlab::compare {
namespace {

void require_same_size(const Plane& a, const Plane& b, const char* what) {
    if (a.width != b.width || a.height != b.height)
        fail("compare: {}: images of different sizes ({}x{} and {}x{})", what, a.width, a.height,
             b.width, b.height);
}

void require_mask(const Plane& p, const Mask& mask, const char* what) {
    if (mask.size() != p.values.size())
        fail("compare: {}: mask of {} pixels for a {}x{} image", what, mask.size(), p.width,
             p.height);
}

}  // namespace

std::pair<double, double> sample_mean_variance(const std::vector<double>& x) {
    if (x.empty()) return {0.0, 0.0};
    double m = 0.0;
    for (double v : x) m += v;
    m /= double(x.size());
    if (x.size() < 2) return {m, 0.0};
    double s = 0.0;
    for (double v : x) s += (v - m) * (v - m);
    return {m, s / double(x.size() - 1)};
}

MeanEstimate mean_with_standard_error(const std::vector<double>& x) {
    const auto [m, v] = sample_mean_variance(x);
    return {m, x.size() > 1 ? std::sqrt(v / double(x.size())) : 0.0};
}

PixelFaults count_pixel_faults(const Image& image) {
    PixelFaults f;
    for (const glm::vec3& p : image.pixels) {
        bool nan = false, inf = false, neg = false;
        for (int c = 0; c < 3; ++c) {
            nan |= std::isnan(p[c]);
            inf |= std::isinf(p[c]);
            neg |= p[c] < 0.0f;
        }
        f.nan += nan, f.inf += inf, f.negative += neg;
    }
    return f;
}

Plane luminance_plane(const Image& image) {
    Plane p(image.width, image.height);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const float y = luminance(image.pixels[i]);
        p.values[i] = std::isfinite(y) ? y : 0.0f;
    }
    return p;
}

double masked_mean(const Plane& plane, const Mask& mask) {
    require_mask(plane, mask, "masked mean");
    double sum = 0.0;
    int64_t n = 0;
    for (size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) sum += plane.values[i], ++n;
    return n > 0 ? sum / double(n) : 0.0;
}

MeanError mean_relative_error(const std::vector<double>& model_means,
                              const std::vector<double>& truth_means) {
    if (model_means.empty() || truth_means.empty())
        fail("compare: the mean error needs at least one realization of each image");
    const auto [m, vm] = sample_mean_variance(model_means);
    const auto [g, vg] = sample_mean_variance(truth_means);
    MeanError e;
    if (!(g > 0.0)) {
        // A black ground truth: no relative error is defined; equal images
        // still have none.
        e.relative_error = m == g ? 0.0 : std::numeric_limits<double>::infinity();
        return e;
    }
    e.relative_error = (m - g) / g;
    e.standard_error =
        std::sqrt(vm / double(model_means.size()) + vg / double(truth_means.size())) / g;
    return e;
}

Plane gaussian_blur(const Plane& plane, double sigma_px) {
    if (!(sigma_px > 0.0)) return plane;
    const int r = std::max(1, int(std::ceil(3.0 * sigma_px)));
    std::vector<double> k(size_t(2 * r + 1));
    double sum = 0.0;
    for (int i = -r; i <= r; ++i)
        sum += k[size_t(i + r)] = std::exp(-0.5 * double(i) * double(i) / (sigma_px * sigma_px));
    for (double& v : k) v /= sum;
    const int w = plane.width, h = plane.height;
    Plane tmp(w, h), out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0.0;
            for (int i = -r; i <= r; ++i)
                s += k[size_t(i + r)] * plane.values[size_t(y) * w + std::clamp(x + i, 0, w - 1)];
            tmp.values[size_t(y) * w + x] = float(s);
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0.0;
            for (int i = -r; i <= r; ++i)
                s += k[size_t(i + r)] * tmp.values[size_t(std::clamp(y + i, 0, h - 1)) * w + x];
            out.values[size_t(y) * w + x] = float(s);
        }
    return out;
}

double blurred_relative_rmse(const Plane& model, const Plane& truth, const Mask& mask,
                             double sigma_px) {
    require_same_size(model, truth, "blurred RMSE");
    require_mask(model, mask, "blurred RMSE");
    const Plane bm = gaussian_blur(model, sigma_px), bg = gaussian_blur(truth, sigma_px);
    double se = 0.0, sg = 0.0;
    int64_t n = 0;
    for (size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) {
            const double d = double(bm.values[i]) - double(bg.values[i]);
            se += d * d, sg += bg.values[i], ++n;
        }
    if (n == 0) return 0.0;
    const double mean = sg / double(n);
    const double rmse = std::sqrt(se / double(n));
    if (!(mean > 0.0)) return rmse == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
    return rmse / mean;
}

double sparkle_blur_sigma(int width, int height) {
    return std::max(1.5, double(std::min(width, height)) / 32.0);
}

double mean_pixel_variance(const std::vector<Plane>& realizations, const Mask& mask) {
    if (realizations.size() < 2) fail("compare: a pixel variance needs at least 2 realizations");
    for (const Plane& p : realizations) {
        require_same_size(p, realizations[0], "pixel variance");
        require_mask(p, mask, "pixel variance");
    }
    const double r = double(realizations.size());
    double total = 0.0;
    int64_t n = 0;
    for (size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        double m = 0.0;
        for (const Plane& p : realizations) m += p.values[i];
        m /= r;
        double s = 0.0;
        for (const Plane& p : realizations) s += (p.values[i] - m) * (p.values[i] - m);
        total += s / (r - 1.0), ++n;
    }
    return n > 0 ? total / double(n) : 0.0;
}

double sampling_pixel_variance(const Plane& a, const Plane& b, const Mask& mask) {
    // The sample variance of two values is (a - b)^2 / 2.
    return mean_pixel_variance({a, b}, mask);
}

double wasserstein1(std::vector<float> a, std::vector<float> b) {
    if (a.empty() || b.empty()) fail("compare: a Wasserstein distance needs two non-empty samples");
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    // Walk the merged support: between consecutive breakpoints both
    // empirical CDFs are constant, F_a = i / |a| and F_b = j / |b|.
    const double na = double(a.size()), nb = double(b.size());
    size_t i = 0, j = 0;
    double x = std::min(a[0], b[0]), w = 0.0;
    while (i < a.size() || j < b.size()) {
        double next;
        if (j >= b.size() || (i < a.size() && a[i] <= b[j]))
            next = a[i];
        else
            next = b[j];
        w += std::abs(double(i) / na - double(j) / nb) * (next - x);
        x = next;
        while (i < a.size() && a[i] == next) ++i;
        while (j < b.size() && b[j] == next) ++j;
    }
    return w;
}

std::vector<float> pooled_masked_values(const std::vector<Plane>& realizations, const Mask& mask) {
    std::vector<float> v;
    for (const Plane& p : realizations) {
        require_mask(p, mask, "pooled values");
        for (size_t i = 0; i < mask.size(); ++i)
            if (mask[i]) v.push_back(p.values[i]);
    }
    return v;
}

double flicker(const std::vector<Plane>& frames, const std::vector<Mask>& masks) {
    if (frames.size() < 2) fail("compare: a flicker measure needs at least 2 frames");
    if (masks.size() != frames.size()) fail("compare: flicker: one mask per frame is needed");
    double total = 0.0;
    int pairs = 0;
    for (size_t t = 0; t + 1 < frames.size(); ++t) {
        const Plane &a = frames[t], &b = frames[t + 1];
        require_same_size(a, b, "flicker");
        require_mask(a, masks[t], "flicker");
        require_mask(b, masks[t + 1], "flicker");
        double diff = 0.0, level = 0.0;
        for (size_t i = 0; i < a.values.size(); ++i)
            if (masks[t][i] && masks[t + 1][i]) {
                diff += std::abs(double(b.values[i]) - double(a.values[i]));
                level += 0.5 * (double(a.values[i]) + double(b.values[i]));
            }
        if (level > 0.0) total += diff / level, ++pairs;
    }
    return pairs > 0 ? total / pairs : 0.0;
}

FlickerEstimate flicker_over_paths(const std::vector<std::vector<Plane>>& paths,
                                   const std::vector<Mask>& masks) {
    if (paths.empty()) fail("compare: a flicker measure needs at least one camera path");
    std::vector<double> values;
    values.reserve(paths.size());
    for (const std::vector<Plane>& frames : paths) values.push_back(flicker(frames, masks));
    return mean_with_standard_error(values);
}

Plane average(const std::vector<Plane>& planes) {
    if (planes.empty()) fail("compare: nothing to average");
    Plane out(planes[0].width, planes[0].height);
    for (const Plane& p : planes) {
        require_same_size(p, planes[0], "average");
        for (size_t i = 0; i < p.values.size(); ++i) out.values[i] += p.values[i];
    }
    for (float& v : out.values) v /= float(planes.size());
    return out;
}

}  // namespace glintlab::compare
