// Sampling of the distribution of visible normals
//   D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo.z        (Heitz 2014, Smith G1)
// for an observer direction wo with wo.z > 0 (callers flip wo into the upper
// hemisphere first). Both samplers map two uniforms in [0,1)^2 to a unit m.
//  - GGX: Heitz 2018 "Sampling the GGX Distribution of Visible Normals" (JCGT 7(4)),
//    Listing 1: stretch, sample the projected hemisphere, unstretch.
//  - Beckmann: Heitz & d'Eon 2014 "Importance Sampling Microfacet-Based BSDFs
//    using the Distribution of Visible Normals" (EGSR), §4: stretch wo to the
//    alpha = 1 configuration, sample the visible slope marginal in x by inverting
//    its CDF, the independent Gaussian slope in y, rotate and unstretch (the
//    structure of pbrt-v3 BeckmannSample11). The inversions here are safeguarded
//    Newton iterations on the exact CDFs instead of fitted approximations.
#ifndef GLINTLAB_MICROFACET_VNDF_GLSL
#define GLINTLAB_MICROFACET_VNDF_GLSL

#include "glintlab/core/constants.glsl"
#include "glintlab/microfacet/erf.glsl"
#include "glintlab/microfacet/masking.glsl"
#include "glintlab/microfacet/ndf.glsl"

// What Listing 1 computes from wo alone (sections 1-2 and the squeeze
// factor of section 3), so that a caller drawing many samples for one wo
// (kneiphof2025's lobe) does it once; sample_vndf_ggx_in then does the same
// operations in the same order as sample_vndf_ggx.
struct VndfGgxFrame {
    vec3 v;
    vec3 t1;
    vec3 t2;
    float s;
};
VndfGgxFrame vndf_ggx_frame(vec3 wo, float alpha_x, float alpha_y) {
    VndfGgxFrame f;
    // Heitz 2018 Listing 1, section 1: observer direction in the hemisphere
    // configuration (alpha = 1), where visible normals are uniform on the
    // projected hemisphere.
    f.v = normalize(vec3(alpha_x * wo.x, alpha_y * wo.y, wo.z));
    // Section 2: orthonormal basis around v (any when v is the normal).
    float len2 = f.v.x * f.v.x + f.v.y * f.v.y;
    f.t1 = len2 > 0.0f ? vec3(-f.v.y, f.v.x, 0.0f) / sqrt(len2) : vec3(1.0f, 0.0f, 0.0f);
    f.t2 = cross(f.v, f.t1);
    f.s = 0.5f * (1.0f + f.v.z);
    return f;
}
vec3 sample_vndf_ggx_in(VndfGgxFrame f, float alpha_x, float alpha_y, vec2 u) {
    // Section 3: uniform point on the unit disk, then squeeze the half of the
    // disk that the visible hemisphere projects to (factor (1 + v.z) / 2).
    float r = sqrt(u.x);
    float phi = TWO_PI * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    p2 = (1.0f - f.s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + f.s * p2;
    // Section 4: lift onto the hemisphere.
    vec3 nh = p1 * f.t1 + p2 * f.t2 + sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * f.v;
    // Section 5: back to the ellipsoid configuration (normals transform with
    // the inverse transpose of the stretch).
    return normalize(vec3(alpha_x * nh.x, alpha_y * nh.y, max(0.0f, nh.z)));
}
vec3 sample_vndf_ggx(vec3 wo, float alpha_x, float alpha_y, vec2 u) {
    return sample_vndf_ggx_in(vndf_ggx_frame(wo, alpha_x, alpha_y), alpha_x, alpha_y, u);
}

// CDF (unnormalised) of the visible x-slope for alpha = 1 and an observer at
// cot(theta) = c in the xz-plane: integral over x' < x of (c - x') exp(-x'^2)/sqrt(pi),
// Heitz & d'Eon 2014 §4.2: C(x) = c (1 + erf x) / 2 + exp(-x^2) / (2 sqrt(pi)).
float vndf_beckmann_cdf_x(float x, float c) {
    return 0.5f * c * (1.0f + erf_approx(x)) + 0.5f * INV_SQRT_PI * exp(-x * x);
}

// Starting point for erf^-1(z), |z| < 1: Winitzki 2008 "A handy approximation
// for the error function and its inverse" (a = 0.147), relative error ~2e-3,
// which the Newton iterations below then polish in two or three steps.
float vndf_erf_inverse_guess(float z) {
    float l = log(max(1e-30f, (1.0f - z) * (1.0f + z)));
    float b = 2.0f / (PI * 0.147f) + 0.5f * l;
    float y = sqrt(max(0.0f, sqrt(b * b - l / 0.147f) - b));
    return z < 0.0f ? -y : y;
}

// Inverts C(x) = u C(c) on x in (-inf, c] by Newton steps kept inside a
// shrinking bracket (bisection when Newton leaves it). C is increasing there
// with C'(x) = (c - x) exp(-x^2) / sqrt(pi).
float vndf_beckmann_invert_x(float u, float c) {
    float lo = -6.0f;  // C(-6) / C(c) < 1e-16: below float resolution of u
    float hi = min(c, 6.0f);
    float total = vndf_beckmann_cdf_x(c, c);
    float target = u * total;
    // Residuals below the float noise of C (erf_approx is exact to ~1.2e-7
    // absolute, scaled by c / 2) cannot steer x any further.
    float noise = 2.5e-7f * total;
    // Two cheap starts, exact in the limits: c -> inf (plain Gaussian,
    // x = erf^-1(2u - 1)) and c = 0 (C = exp(-x^2) / (2 sqrt(pi)), x = -sqrt(-ln u)).
    // Keep the one with the smaller residual.
    float x_far = clamp(vndf_erf_inverse_guess(2.0f * u - 1.0f), lo, hi);
    float x_grazing = clamp(-sqrt(-log(max(u, 1e-30f))), lo, hi);
    float r_far = abs(vndf_beckmann_cdf_x(x_far, c) - target);
    float r_grazing = abs(vndf_beckmann_cdf_x(x_grazing, c) - target);
    float x = r_far < r_grazing ? x_far : x_grazing;
    for (int i = 0; i < 48; ++i) {
        float f = vndf_beckmann_cdf_x(x, c) - target;
        if (abs(f) <= noise) break;
        if (f > 0.0f) hi = x;
        else lo = x;
        float d = (c - x) * INV_SQRT_PI * exp(-x * x);
        float xn = d > 0.0f ? x - f / d : 0.5f * (lo + hi);
        if (!(xn > lo && xn < hi)) xn = 0.5f * (lo + hi);
        bool done = abs(xn - x) < 1e-6f * max(1.0f, abs(x));
        x = xn;
        if (done || hi - lo < 1e-6f) break;
    }
    return x;
}

// y-slope for alpha = 1 is N(0, 1/2): y = erf^-1(z), z = 2u - 1, found by the
// same safeguarded Newton iteration (erf'(y) = 2 exp(-y^2) / sqrt(pi)).
float vndf_erf_inverse(float z) {
    float lo = -4.0f;  // erf_approx saturates to +-1 at |y| = 4
    float hi = 4.0f;
    float y = clamp(vndf_erf_inverse_guess(z), lo, hi);
    for (int i = 0; i < 48; ++i) {
        float f = erf_approx(y) - z;
        if (abs(f) <= 1.5e-7f) break;  // the accuracy of erf_approx
        if (f > 0.0f) hi = y;
        else lo = y;
        float d = 2.0f * INV_SQRT_PI * exp(-y * y);
        float yn = y - f / d;
        if (!(yn > lo && yn < hi)) yn = 0.5f * (lo + hi);
        bool done = abs(yn - y) < 1e-6f * max(1.0f, abs(y));
        y = yn;
        if (done || hi - lo < 1e-6f) break;
    }
    return y;
}

vec3 sample_vndf_beckmann(vec3 wo, float alpha_x, float alpha_y, vec2 u) {
    // Stretch wo into the alpha = 1 configuration (Heitz & d'Eon 2014 §4.1).
    vec3 v = normalize(vec3(alpha_x * wo.x, alpha_y * wo.y, wo.z));
    float sin_t = sqrt(v.x * v.x + v.y * v.y);
    float sx;
    float sy;
    if (sin_t < 1e-5f) {
        // Observer at the normal: the visible weight (cot - x) / cot is 1 to
        // within 1e-5 x, so slopes are the plain isotropic Gaussian; polar
        // Box-Muller with r^2 ~ Exp(1).
        float r = sqrt(-log(1.0f - u.x));
        float phi = TWO_PI * u.y;
        sx = r * cos(phi);
        sy = r * sin(phi);
    } else {
        float cot_t = v.z / sin_t;
        float x = vndf_beckmann_invert_x(u.x, cot_t);
        float z = clamp(2.0f * u.y - 1.0f, -ONE_MINUS_EPSILON, ONE_MINUS_EPSILON);
        float y = vndf_erf_inverse(z);
        // Rotate from the observer's azimuth frame to the tangent frame.
        float c = v.x / sin_t;
        float s = v.y / sin_t;
        sx = c * x - s * y;
        sy = s * x + c * y;
    }
    // Unstretch slopes and convert the slope to a normal: m ~ (-sx, -sy, 1).
    return normalize(vec3(-alpha_x * sx, -alpha_y * sy, 1.0f));
}

vec3 sample_vndf(int ndf, vec3 wo, float alpha_x, float alpha_y, vec2 u) {
    if (ndf == NDF_BECKMANN) return sample_vndf_beckmann(wo, alpha_x, alpha_y, u);
    return sample_vndf_ggx(wo, alpha_x, alpha_y, u);
}

// Density of sample_vndf in solid angle of m (the visible NDF above), for wo.z > 0.
float pdf_vndf(int ndf, vec3 wo, vec3 m, float alpha_x, float alpha_y) {
    if (wo.z <= 0.0f) return 0.0f;
    float wm = max(0.0f, dot(wo, m));
    return G1_Smith(ndf, wo, alpha_x, alpha_y) * wm * D_Microfacet(ndf, m, alpha_x, alpha_y) /
           wo.z;
}

#endif
