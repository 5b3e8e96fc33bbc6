#include "glintlab/core/radical_inverse.h"

#include <gtest/gtest.h>

namespace glintlab {
namespace {

// The first points of van der Corput's sequence, a full reversal, and the
// float form as the double rounded to nearest.
TEST(RadicalInverse, MirrorsTheBitsAboutThePoint) {
    EXPECT_EQ(reverse_bits(1u), 0x80000000u);
    EXPECT_EQ(reverse_bits(0x80000000u), 1u);
    EXPECT_EQ(reverse_bits(0x12345678u), 0x1e6a2c48u);
    const double expected[8] = {0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
    for (uint32_t i = 0; i < 8; ++i) EXPECT_EQ(radical_inverse(i), expected[i]) << i;
    for (uint32_t i : {1u, 7u, 12345u, 0xffffffffu})
        EXPECT_EQ(radical_inverse_f(i), static_cast<float>(radical_inverse(i))) << i;
    EXPECT_LT(radical_inverse(0xffffffffu), 1.0);
}

}  // namespace
}  // namespace glintlab
