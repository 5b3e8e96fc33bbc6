// Masking-shadowing functions. Smith forms from Heitz 2014 "Understanding the
// Masking-Shadowing Function in Microfacet-Based BRDFs" (JCGT 3(2)); V-cavity
// from Cook & Torrance 1982 as restated in chermain2020 (paper 004) Eq. 15-16.
// All directions local (z = normal).
#ifndef GLINTLAB_MICROFACET_MASKING_GLSL
#define GLINTLAB_MICROFACET_MASKING_GLSL

#include "glintlab/core/constants.glsl"
#include "glintlab/microfacet/erf.glsl"
#include "glintlab/microfacet/ndf.glsl"

// 1 / a = alpha(phi) tan(theta) with alpha(phi)^2 = cos^2 phi ax^2 + sin^2 phi ay^2
// (Heitz 2014: the anisotropic roughness projected on the direction's azimuth);
// returned squared: (ax^2 x^2 + ay^2 y^2) / z^2. Symmetric in the sign of w.z.
float masking_alpha_tan2(vec3 w, float alpha_x, float alpha_y) {
    float ax = alpha_x * w.x;
    float ay = alpha_y * w.y;
    return (ax * ax + ay * ay) / (w.z * w.z);
}

// The same for slopes correlated by rho (D_Microfacet_correlated): Smith's
// Lambda depends on the slope distribution only through its marginal along
// the direction's azimuth (Heitz 2014 §5.3), whose variance the slope matrix
// [[ax², ρ ax ay], [ρ ax ay, ay²]] gives: (ax² x² + 2ρ ax ay x y + ay² y²) / z².
float masking_alpha_tan2_correlated(vec3 w, float alpha_x, float alpha_y, float rho) {
    float ax = alpha_x * w.x;
    float ay = alpha_y * w.y;
    return max(ax * ax + ay * ay + 2.0f * rho * ax * ay, 0.0f) / (w.z * w.z);
}

// Heitz 2014 Eq. 72 with a = 1 / (alpha tan theta), t2 = 1 / a^2:
//   Lambda = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)).
float Lambda_Beckmann_tan2(float t2) {
    if (t2 == 0.0f) return 0.0f;  // normal incidence
    float a = 1.0f / sqrt(t2);
    return 0.5f * (erf_approx(a) - 1.0f) + exp(-a * a) / (2.0f * a * SQRT_PI);
}

// Heitz 2014 Eq. 86: Lambda = (-1 + sqrt(1 + 1/a^2)) / 2; sqrt(1+t2)-1
// rewritten as t2/(sqrt(1+t2)+1) to avoid cancellation at small t2.
float Lambda_GGX_tan2(float t2) { return 0.5f * t2 / (sqrt(1.0f + t2) + 1.0f); }

float Lambda_Beckmann(vec3 w, float alpha_x, float alpha_y) {
    if (w.z == 0.0f) return 1e30f;  // grazing: fully masked
    return Lambda_Beckmann_tan2(masking_alpha_tan2(w, alpha_x, alpha_y));
}

float Lambda_GGX(vec3 w, float alpha_x, float alpha_y) {
    if (w.z == 0.0f) return 1e30f;
    return Lambda_GGX_tan2(masking_alpha_tan2(w, alpha_x, alpha_y));
}

float Lambda_Microfacet(int ndf, vec3 w, float alpha_x, float alpha_y) {
    if (ndf == NDF_BECKMANN) return Lambda_Beckmann(w, alpha_x, alpha_y);
    return Lambda_GGX(w, alpha_x, alpha_y);
}

// Lambda of D_Microfacet_correlated; rho = 0: Lambda_Microfacet.
float Lambda_Microfacet_correlated(int ndf, vec3 w, float alpha_x, float alpha_y, float rho) {
    if (w.z == 0.0f) return 1e30f;
    float t2 = masking_alpha_tan2_correlated(w, alpha_x, alpha_y, rho);
    return ndf == NDF_BECKMANN ? Lambda_Beckmann_tan2(t2) : Lambda_GGX_tan2(t2);
}

// Smith masking without the microfacet Heaviside factor (Heitz 2014, Smith G1):
// G1(w) = 1 / (1 + Lambda(w)). Callers multiply by H(w.m) where needed.
float G1_Smith(int ndf, vec3 w, float alpha_x, float alpha_y) {
    return 1.0f / (1.0f + Lambda_Microfacet(ndf, w, alpha_x, alpha_y));
}

// Height-correlated Smith masking-shadowing (Heitz 2014, height-correlated Smith), reflection and
// transmission alike (Lambda is even in w.z): 1 / (1 + Lambda(o) + Lambda(i)).
float G2_SmithCorrelated(int ndf, vec3 wo, vec3 wi, float alpha_x, float alpha_y) {
    return 1.0f / (1.0f + Lambda_Microfacet(ndf, wo, alpha_x, alpha_y) +
                   Lambda_Microfacet(ndf, wi, alpha_x, alpha_y));
}

// The same for slopes correlated by rho (D_Microfacet_correlated).
float G2_SmithCorrelated_sheared(int ndf, vec3 wo, vec3 wi, float alpha_x, float alpha_y,
                                 float rho) {
    return 1.0f / (1.0f + Lambda_Microfacet_correlated(ndf, wo, alpha_x, alpha_y, rho) +
                   Lambda_Microfacet_correlated(ndf, wi, alpha_x, alpha_y, rho));
}

// Separable (uncorrelated) Smith masking-shadowing (Heitz 2014, separable Smith): G1(o) G1(i).
float G2_SmithSeparable(int ndf, vec3 wo, vec3 wi, float alpha_x, float alpha_y) {
    return G1_Smith(ndf, wo, alpha_x, alpha_y) * G1_Smith(ndf, wi, alpha_x, alpha_y);
}

// V-cavity masking, chermain2020 Eq. 16 (Cook & Torrance 1982):
//   G1(w, m) = H(w.m) min(1, 2 (m.n)(w.n) / (w.m)).
// The cavity is the symmetric pair {m, (-m.x, -m.y, m.z)}; it does not depend on
// the NDF, and for any NDF with D(m) = D(-m.x, -m.y, m.z) (Beckmann and GGX) the
// visible projected areas of the pair sum to the projected area of the groove,
// so the weak white furnace holds exactly. Only for w above the macrosurface
// (w.z > 0); below it the geometric normal faces away and G1 = 0.
float G1_VCavity(vec3 w, vec3 m) {
    float wm = dot(w, m);
    if (wm <= 0.0f || w.z <= 0.0f || m.z <= 0.0f) return 0.0f;
    return min(1.0f, 2.0f * m.z * w.z / wm);
}

// chermain2020 Eq. 15: G2 = G1(o, m) G1(i, m) (separable product, the form 004
// uses; Cook & Torrance's original took min(G1(o), G1(i)), see G2_VCavityMin).
float G2_VCavity(vec3 wo, vec3 wi, vec3 m) { return G1_VCavity(wo, m) * G1_VCavity(wi, m); }

// Cook & Torrance 1982 form: min(1, G1(o), G1(i)) (both <= 1 already).
float G2_VCavityMin(vec3 wo, vec3 wi, vec3 m) { return min(G1_VCavity(wo, m), G1_VCavity(wi, m)); }

#endif
