// Bit reversal and van der Corput's base-2 radical inverse: the coordinate
// of the low-discrepancy point sets several parts use (Hammersley points of
// a prefilter's kernel and of an environment source's texels, the (0,2)
// rule of jakob2014's footprint integral).
#pragma once

#include <cstdint>

namespace glintlab {

// The 32 bits of x in reverse order.
constexpr uint32_t reverse_bits(uint32_t x) {
    x = ((x >> 1u) & 0x55555555u) | ((x & 0x55555555u) << 1u);
    x = ((x >> 2u) & 0x33333333u) | ((x & 0x33333333u) << 2u);
    x = ((x >> 4u) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4u);
    x = ((x >> 8u) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8u);
    return (x >> 16u) | (x << 16u);
}

// The bits of i mirrored about the binary point, in [0, 1): exact in double,
// rounded to nearest in float.
constexpr double radical_inverse(uint32_t i) {
    return reverse_bits(i) * 0x1p-32;
}
constexpr float radical_inverse_f(uint32_t i) {
    return static_cast<float>(reverse_bits(i)) * 0x1p-32f;
}

}  // namespace glintlab
