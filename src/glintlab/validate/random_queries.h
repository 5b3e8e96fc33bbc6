// Inputs shared by the glint models' validation experiments: oriented
// footprints, half vectors, log-uniform draws, and the random "robustness"
// queries (any half vector, footprint and material over many decades) that
// every model must evaluate to a finite, non-negative D_P. The draw order is
// fixed: suites reproduce their published numbers for a given seed.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/core/rng.h"

namespace glintlab {

// A footprint whose ellipse has the given minor width, ratio and major-axis
// angle: orthogonal pixel steps along the major and minor axes.
Footprint oriented_footprint(glm::vec2 uv, double minor, double ratio, double angle);

// The half vector at tan(theta_h) and azimuth phi.
glm::vec3 half_vector_at(double tan_theta, double phi);

// 10^x with x uniform in [lo_exp10, hi_exp10).
double pow10_uniform(Pcg32& rng, double lo_exp10, double hi_exp10);

// One random query of a robustness sweep: the half vector is the normal,
// grazing, or uniform on the sphere (half below the horizon); the footprint
// has any minor width (1e-25 to 1e15) and ratio (up to 1e12), or is zero or
// collinear; the target NDF, roughness (1e-3 to 1), log density (-20 to 60,
// with both ends drawn exactly) and seed are random.
struct RobustnessQuery {
    glm::vec3 h{0.0f, 0.0f, 1.0f};
    Footprint footprint{};
    int ndf = 0;  // shader::NDF_BECKMANN or shader::NDF_GGX
    float alpha_x = 0.3f, alpha_y = 0.3f;
    float log_density = 20.0f;
    uint32_t seed = 0;
};
RobustnessQuery draw_robustness_query(Pcg32& rng);

// The convergence experiments' estimate of E[D_P(h)]: the mean of
// ndf(footprint, pattern_seed) over n footprints of minor width 1e-3 uv,
// ratio log-uniform in [1, 8), any angle, uv in [0, 16)^2, each with a fresh
// pattern seed (draw order: seed, uv, ratio, angle).
template <class Ndf>
double mean_over_random_footprints(Pcg32& rng, int n, Ndf&& ndf) {
    constexpr double kPi = 3.14159265358979323846;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const uint32_t seed = rng.next_uint();
        const glm::vec2 uv(rng.next_float() * 16.0f, rng.next_float() * 16.0f);
        const Footprint fp = oriented_footprint(uv, 1e-3, pow10_uniform(rng, 0.0, std::log10(8.0)),
                                                rng.next_double() * kPi);
        sum += ndf(fp, seed);
    }
    return sum / n;
}

}  // namespace glintlab
