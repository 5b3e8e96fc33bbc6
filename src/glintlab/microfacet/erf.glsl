// Error function for shading code (GLSL has no erf). Own fit, float32, max
// |erf_approx(x) - erf(x)| < 1.2e-7 for all x (measured against std::erf in
// erf_test.cpp on a dense grid; budget 2e-7).
//  - |x| < 0.75: Maclaurin series erf(x) = 2/sqrt(pi) sum_n (-1)^n x^(2n+1) / (n! (2n+1))
//    (Abramowitz & Stegun 7.1.5), 11 terms, truncation < 1e-12; every term is
//    below 1 so float rounding stays near one ulp.
//  - 0.75 <= |x| < 4: erf = 1 - exp(-x^2) R(x) with R(x) = exp(x^2) erfc(x), an
//    entire, slowly varying function, interpolated by a degree-11 polynomial in
//    t = (x - 2.375) / 1.625 in [-1, 1] (Chebyshev interpolation at 64 nodes in
//    double, converted to monomials). erfc <= 0.29 there, so the rounding error
//    of the product is scaled down by erfc.
//  - |x| >= 4: erfc(4) = 1.5e-8, so erf = +-1 within the budget.
#ifndef GLINTLAB_MICROFACET_ERF_GLSL
#define GLINTLAB_MICROFACET_ERF_GLSL

#include "glintlab/core/constants.glsl"

float erf_approx(float x) {
    float ax = abs(x);
    float r;
    if (ax < 0.75f) {
        float x2 = ax * ax;
        // Horner in x^2 over the coefficients (-1)^n / (n! (2n+1)), n = 10 .. 0.
        float c = 1.0f / 76204800.0f;  // n = 10
        c = c * x2 - 1.0f / 6894720.0f;
        c = c * x2 + 1.0f / 685440.0f;
        c = c * x2 - 1.0f / 75600.0f;
        c = c * x2 + 1.0f / 9360.0f;
        c = c * x2 - 1.0f / 1320.0f;
        c = c * x2 + 1.0f / 216.0f;
        c = c * x2 - 1.0f / 42.0f;
        c = c * x2 + 1.0f / 10.0f;
        c = c * x2 - 1.0f / 3.0f;
        c = c * x2 + 1.0f;  // n = 0
        r = (2.0f * INV_SQRT_PI) * ax * c;
    } else if (ax < 4.0f) {
        float t = (ax - 2.375f) / 1.625f;
        float q = -0.000143692191f;
        q = q * t + 0.000337439657f;
        q = q * t - 0.000377011703f;
        q = q * t + 0.000875118406f;
        q = q * t - 0.00237131827f;
        q = q * t + 0.00507064441f;
        q = q * t - 0.0103298635f;
        q = q * t + 0.020751624f;
        q = q * t - 0.0401594434f;
        q = q * t + 0.0744280329f;
        q = q * t - 0.131587761f;
        q = q * t + 0.220505664f;
        r = 1.0f - exp(-ax * ax) * q;
    } else {
        r = 1.0f;
    }
    return x < 0.0f ? -r : r;
}

#endif
