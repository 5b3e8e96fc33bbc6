#include "glintlab/core/distribution.h"

#include <algorithm>
#include <cmath>

#include "glintlab/core/error.h"

namespace glintlab {

Distribution1D::Distribution1D(std::span<const float> weights)
    : func_(weights.begin(), weights.end()), cdf_(weights.size() + 1, 0.0) {
    if (func_.empty()) fail("Distribution1D: no weights");
    const double n = static_cast<double>(func_.size());
    for (size_t i = 0; i < func_.size(); ++i) {
        if (!(func_[i] >= 0.0f) || !std::isfinite(func_[i]))
            fail("Distribution1D: weight {} = {} is not a finite non-negative number", i, func_[i]);
        cdf_[i + 1] = cdf_[i] + func_[i] / n;
    }
    const double total = cdf_.back();
    integral_ = static_cast<float>(total);
    if (total == 0.0) {
        // All-zero function: fall back to uniform sampling (pbrt-v4 does the same).
        for (size_t i = 1; i < cdf_.size(); ++i) cdf_[i] = static_cast<double>(i) / n;
    } else {
        for (size_t i = 1; i < cdf_.size(); ++i) cdf_[i] /= total;
    }
}

float Distribution1D::sample(float u, float* pdf, int* index) const {
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), static_cast<double>(u));
    const int i = std::clamp(static_cast<int>(it - cdf_.begin()) - 1, 0, size() - 1);
    if (index) *index = i;
    const double width = cdf_[i + 1] - cdf_[i];
    double du = static_cast<double>(u) - cdf_[i];
    if (width > 0.0) du /= width;
    if (pdf) *pdf = integral_ > 0.0f ? func_[i] / integral_ : 1.0f;
    float x = std::min(static_cast<float>((i + du) / static_cast<double>(size())), 0.99999994f);
    // Rounding to float can move x across a cell boundary; pdf(x) must see
    // the cell that was sampled, so nudge x back inside it.
    const float n = static_cast<float>(size());
    while (x > 0.0f && static_cast<int>(x * n) > i) x = std::nextafter(x, 0.0f);
    while (x < 1.0f && static_cast<int>(x * n) < i) x = std::nextafter(x, 1.0f);
    return x;
}

float Distribution1D::pdf(float x) const {
    const int i = std::clamp(static_cast<int>(x * static_cast<float>(size())), 0, size() - 1);
    return integral_ > 0.0f ? func_[i] / integral_ : 1.0f;
}

Distribution2D::Distribution2D(std::span<const float> weights, int width, int height) {
    if (width <= 0 || height <= 0 || weights.size() != static_cast<size_t>(width) * height)
        fail("Distribution2D: {} weights for a {}x{} grid", weights.size(), width, height);
    std::vector<float> marginal(height);
    conditional_.reserve(height);
    for (int y = 0; y < height; ++y) {
        conditional_.emplace_back(weights.subspan(static_cast<size_t>(y) * width, width));
        marginal[y] = conditional_.back().integral();
    }
    marginal_ = Distribution1D(marginal);
}

glm::vec2 Distribution2D::sample(glm::vec2 u, float* pdf) const {
    float pdf_y = 0.0f, pdf_x = 0.0f;
    int row = 0;
    const float y = marginal_.sample(u.y, &pdf_y, &row);
    const float x = conditional_[row].sample(u.x, &pdf_x);
    if (pdf) *pdf = pdf_x * pdf_y;
    return {x, y};
}

float Distribution2D::pdf(glm::vec2 p) const {
    const int rows = static_cast<int>(conditional_.size());
    const int row = std::clamp(static_cast<int>(p.y * static_cast<float>(rows)), 0, rows - 1);
    if (marginal_.integral() <= 0.0f) return 1.0f;
    return conditional_[row].pdf(p.x) * conditional_[row].integral() / marginal_.integral();
}

}  // namespace glintlab
