// Normal distribution functions D(m): Walter et al. 2007 "Microfacet Models for
// Refraction through Rough Surfaces" (Eq. 25 Beckmann, Eq. 33 GGX), in the
// anisotropic forms of Heitz 2014 "Understanding the Masking-Shadowing Function
// in Microfacet-Based BRDFs" (the ellipsoidal NDFs of its §5, whose Lambda are
// its Eq. 72 and Eq. 86).
// m is a unit vector in the local shading frame (z = normal); alpha_x and
// alpha_y are the roughnesses along the tangent x and bitangent y axes.
// Both are normalised as projected areas: integral of D(m) m.z dm = 1.
#ifndef GLINTLAB_MICROFACET_NDF_GLSL
#define GLINTLAB_MICROFACET_NDF_GLSL

#include "glintlab/core/constants.glsl"

const int NDF_BECKMANN = 0;
const int NDF_GGX = 1;

// Squared slope length in the "stretched" space where the distribution is
// isotropic with alpha = 1: (x_m / alpha_x)^2 + (y_m / alpha_y)^2 over z_m^2
// times z_m^2, i.e. the numerator of tan^2(theta) (cos^2 phi / ax^2 + sin^2 phi / ay^2).
float ndf_stretched_xy2(vec3 m, float alpha_x, float alpha_y) {
    float sx = m.x / alpha_x;
    float sy = m.y / alpha_y;
    return sx * sx + sy * sy;
}

// Anisotropic Beckmann: D = exp(-tan^2(theta) (cos^2 phi/ax^2 + sin^2 phi/ay^2))
//                        / (pi ax ay cos^4 theta).
float D_Beckmann(vec3 m, float alpha_x, float alpha_y) {
    if (m.z <= 0.0f) return 0.0f;
    float cos2 = m.z * m.z;
    float e = ndf_stretched_xy2(m, alpha_x, alpha_y) / cos2;
    return exp(-e) / (PI * alpha_x * alpha_y * cos2 * cos2);
}

// Anisotropic GGX: D = 1 / (pi ax ay cos^4 theta (1 + tan^2 theta (cos^2 phi/ax^2
// + sin^2 phi/ay^2))^2); multiplying through by cos^4 gives the form below,
// which has no tan and stays finite at grazing m.
float D_GGX(vec3 m, float alpha_x, float alpha_y) {
    if (m.z <= 0.0f) return 0.0f;
    float t = ndf_stretched_xy2(m, alpha_x, alpha_y) + m.z * m.z;
    return 1.0f / (PI * alpha_x * alpha_y * t * t);
}

float D_Microfacet(int ndf, vec3 m, float alpha_x, float alpha_y) {
    if (ndf == NDF_BECKMANN) return D_Beckmann(m, alpha_x, alpha_y);
    return D_GGX(m, alpha_x, alpha_y);
}

// The NDF whose slopes are correlated by rho in (−1, 1) (a sheared lobe: the
// slope distribution's matrix [[ax², ρ ax ay], [ρ ax ay, ay²]] in place of
// diag(ax², ay²), Heitz 2014 §5's ellipsoidal NDFs under a linear transform
// of the slopes): the quadratic form (x̃² − 2ρ x̃ ỹ + ỹ²) / (1 − ρ²), x̃ =
// x_m / ax, replaces x̃² + ỹ², and the normalisation gains √(1 − ρ²). A
// normal map's or a curved surface's correlated slope covariance keeps its
// direction this way (Chermain et al. 2021 shear their Beckmann target
// alike). rho = 0: D_Microfacet.
float D_Microfacet_correlated(int ndf, vec3 m, float alpha_x, float alpha_y, float rho) {
    if (rho == 0.0f) return D_Microfacet(ndf, m, alpha_x, alpha_y);
    if (m.z <= 0.0f) return 0.0f;
    float sx = m.x / alpha_x, sy = m.y / alpha_y;
    float one_minus_rho2 = 1.0f - rho * rho;
    float q = (sx * sx - 2.0f * rho * sx * sy + sy * sy) / one_minus_rho2;
    float norm = PI * alpha_x * alpha_y * sqrt(one_minus_rho2);
    float cos2 = m.z * m.z;
    if (ndf == NDF_BECKMANN) return exp(-q / cos2) / (norm * cos2 * cos2);
    float t = q + cos2;
    return 1.0f / (norm * t * t);
}

#endif
