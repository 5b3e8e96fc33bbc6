// Beckmann microfacet terms used by wang2020 (001 §4.4: "all isotropic BRDF
// models with Beckmann normal distribution function"). Local frame: n = +z.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace glintlab::wang2020 {

inline constexpr double kPi = 3.14159265358979323846;

// Beckmann NDF D(h), normalised so that ∫ D(h) (h·n) dh = 1.
inline double beckmann_D(double cos_h, double alpha) {
    if (cos_h <= 0.0) return 0.0;
    const double c2 = cos_h * cos_h;
    const double t2 = (1.0 - c2) / c2;
    const double a2 = alpha * alpha;
    return std::exp(-t2 / a2) / (kPi * a2 * c2 * c2);
}

// Smith Λ for Beckmann (exact erf form).
inline double beckmann_lambda(double cos_v, double alpha) {
    if (cos_v >= 1.0) return 0.0;
    const double tan_v = std::sqrt(std::max(0.0, 1.0 - cos_v * cos_v)) / cos_v;
    const double a = 1.0 / (alpha * tan_v);
    return 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * std::sqrt(kPi));
}

// Height-correlated Smith G2(i, o).
inline double beckmann_G2(double cos_i, double cos_o, double alpha) {
    if (cos_i <= 0.0 || cos_o <= 0.0) return 0.0;
    return 1.0 / (1.0 + beckmann_lambda(cos_i, alpha) + beckmann_lambda(cos_o, alpha));
}

// Direction from spherical angles (local frame, z up).
inline glm::dvec3 spherical_dir(double theta, double phi) {
    const double s = std::sin(theta);
    return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

// Normal drawn from D(m)(m·n) (Beckmann) from two unit numbers:
// tan²θm = −α² ln(1 − u1), φm = 2π u2 (wang2020_tables.glsl
// wang2020_particle_normal is the GPU's float copy).
inline glm::dvec3 beckmann_sample_normal(double u1, double u2, double alpha) {
    const double tan2 = -alpha * alpha * std::log(1.0 - u1);
    const double c = 1.0 / std::sqrt(1.0 + tan2);
    return spherical_dir(std::acos(c), 2.0 * kPi * u2);
}

}  // namespace glintlab::wang2020
