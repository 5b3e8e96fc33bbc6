// Inverse CDF of the standard normal distribution, used by every Gaussian
// counting law to turn one uniform number into a Gaussian deviate.
//
// Phi^-1(u) = sqrt(2) erfinv(2u - 1) with the single-precision erfinv
// polynomials of M. Giles, "Approximating the erfinv function" (GPU Computing
// Gems, 2011): one log, at most one sqrt, no loop. Giles takes
// w = -log((1 - x)(1 + x)); we write (1 - x)(1 + x) = 4 u (1 - u), exact in
// fp32 for small u where 1 + x would cancel. Measured in fp32 against
// Boost.Math's double quantile: max absolute error 1e-6 over u in
// [2^-24, 1 - 2^-24] (normal_quantile_test.cpp checks 1e-5). (Acklam's
// rational approximation, tried first, loses 3e-4 to cancellation in fp32
// near u = 0.025.) The uniform is clamped to that range so |z| <= 5.3.
#ifndef GLINTLAB_COUNTING_NORMAL_QUANTILE_GLSL
#define GLINTLAB_COUNTING_NORMAL_QUANTILE_GLSL

float normal_quantile(float u) {
    float uc = clamp(u, 5.9604645e-8f, 1.0f - 5.9604645e-8f);
    float x = 2.0f * uc - 1.0f;
    float w = -log(4.0f * uc * (1.0f - uc));
    // One polynomial, its coefficients selected per lane, instead of an
    // if/else over the two: the same operations on the same values in each
    // case, but SIMD back ends that run both sides of a branch for a block of
    // pixels (llvmpipe) evaluate one polynomial instead of two.
    bool central = w < 5.0f;  // |z| below ~2.5 standard deviations; else the tails
    float t = central ? w - 2.5f : sqrt(w) - 3.0f;
    float p = central ? 2.81022636e-08f : -0.000200214257f;
    p = (central ? 3.43273939e-07f : 0.000100950558f) + p * t;
    p = (central ? -3.5233877e-06f : 0.00134934322f) + p * t;
    p = (central ? -4.39150654e-06f : -0.00367342844f) + p * t;
    p = (central ? 0.00021858087f : 0.00573950773f) + p * t;
    p = (central ? -0.00125372503f : -0.0076224613f) + p * t;
    p = (central ? -0.00417768164f : 0.00943887047f) + p * t;
    p = (central ? 0.246640727f : 1.00167406f) + p * t;
    p = (central ? 1.50140941f : 2.83297682f) + p * t;
    return 1.41421356f * p * x;
}

#endif
