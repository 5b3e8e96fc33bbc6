// Piecewise-constant 1-D and 2-D distributions for importance sampling
// (pbrt-v4 PiecewiseConstant1D/2D): used for environment-map sampling.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace glintlab {

class Distribution1D {
  public:
    Distribution1D() = default;
    explicit Distribution1D(std::span<const float> weights);  // weights >= 0

    // Continuous sample in [0, 1); pdf is w.r.t. that unit domain.
    float sample(float u, float* pdf, int* index = nullptr) const;
    float pdf(float x) const;
    float integral() const { return integral_; }
    int size() const { return static_cast<int>(func_.size()); }

  private:
    std::vector<float> func_;
    std::vector<double> cdf_;
    float integral_ = 0.0f;
};

class Distribution2D {
  public:
    Distribution2D() = default;
    // weights[y * width + x] >= 0, over the unit square.
    Distribution2D(std::span<const float> weights, int width, int height);

    glm::vec2 sample(glm::vec2 u, float* pdf) const;  // pdf w.r.t. the unit square
    float pdf(glm::vec2 p) const;
    float integral() const { return marginal_.integral(); }

  private:
    std::vector<Distribution1D> conditional_;
    Distribution1D marginal_;
};

}  // namespace glintlab
