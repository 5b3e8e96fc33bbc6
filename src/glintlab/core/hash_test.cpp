#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "glintlab/core/hash.h"
#include "glintlab/core/rng.h"

namespace glintlab {
namespace {

using namespace glintlab::shader;

TEST(Pcg32, MatchesReferenceSequence) {
    // pcg32-demo of the PCG reference implementation: initstate 42, initseq 54.
    Pcg32 rng(54u, 42u);
    const std::array<uint32_t, 6> expected = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                              0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
    for (uint32_t e : expected) EXPECT_EQ(rng.next_uint(), e);
}

TEST(Pcg32, AdvanceSkipsExactly) {
    Pcg32 a(7u, 99u), b(7u, 99u);
    for (int i = 0; i < 1000; ++i) a.next_uint();
    b.advance(1000);
    EXPECT_EQ(a.next_uint(), b.next_uint());
}

TEST(Pcg32, FloatsInUnitInterval) {
    Pcg32 rng(1u, 2u);
    for (int i = 0; i < 100000; ++i) {
        const float u = rng.next_float();
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
    }
}

// Chi-square uniformity over 64 bins; 63 degrees of freedom, critical value
// at significance 1e-3 is 103.4 (a fixed seed makes the test deterministic).
double chi2_uniform(const std::vector<float>& values) {
    std::array<double, 64> bins{};
    for (float v : values) bins[std::min(63, static_cast<int>(v * 64.0f))] += 1.0;
    const double expected = static_cast<double>(values.size()) / 64.0;
    double chi2 = 0.0;
    for (double b : bins) chi2 += (b - expected) * (b - expected) / expected;
    return chi2;
}

TEST(Hash, PcgHashOfSequentialIntegersIsUniform) {
    std::vector<float> v;
    for (uint i = 0; i < 200000u; ++i) v.push_back(uint_to_unit_float(pcg_hash(i)));
    EXPECT_LT(chi2_uniform(v), 103.4);
}

TEST(Hash, TeaOfSequentialIntegersIsUniform) {
    std::vector<float> v;
    for (uint i = 0; i < 200000u; ++i) v.push_back(uint_to_unit_float(tea(uvec2(i, 7u), 8).x));
    EXPECT_LT(chi2_uniform(v), 103.4);
}

TEST(Hash, Pcg3dComponentsAreUniform) {
    std::vector<float> vx, vz;
    for (uint i = 0; i < 100000u; ++i) {
        const uvec3 h = pcg3d(uvec3(i % 317u, i / 317u, 5u));
        vx.push_back(uint_to_unit_float(h.x));
        vz.push_back(uint_to_unit_float(h.z));
    }
    EXPECT_LT(chi2_uniform(vx), 103.4);
    EXPECT_LT(chi2_uniform(vz), 103.4);
}

// Avalanche: flipping one input bit flips each output bit with probability
// 1/2. Averaged over 4096 inputs x 32 bits, the mean flip rate is within 0.01.
template <typename F>
double avalanche(F hash) {
    double flips = 0.0;
    int trials = 0;
    for (uint i = 0; i < 4096u; ++i) {
        const uint x = pcg_hash(i + 12345u);
        for (uint b = 0; b < 32u; ++b) {
            flips += static_cast<double>(std::popcount(hash(x) ^ hash(x ^ (1u << b)))) / 32.0;
            ++trials;
        }
    }
    return flips / trials;
}

TEST(Hash, Avalanche) {
    EXPECT_NEAR(avalanche([](uint x) { return pcg_hash(x); }), 0.5, 0.01);
    EXPECT_NEAR(avalanche([](uint x) { return xxhash32(x); }), 0.5, 0.01);
    EXPECT_NEAR(avalanche([](uint x) { return tea(uvec2(x, 0u), 8).x; }), 0.5, 0.01);
}

TEST(Hash, CellHashesDistinguishNeighbours) {
    std::set<uint> seen;
    for (int y = -50; y < 50; ++y)
        for (int x = -50; x < 50; ++x) seen.insert(hash_cell(ivec2(x, y), 3u));
    EXPECT_EQ(seen.size(), 10000u);
    EXPECT_NE(hash_cell(ivec2(1, 2), 0u), hash_cell(ivec2(2, 1), 0u));
    EXPECT_NE(hash_cell(ivec2(1, 2), 0u), hash_cell(ivec2(1, 2), 1u));
}

TEST(Hash, PixelStreamsAreIndependentOfOrder) {
    Pcg32 a = pixel_stream(10, 20, 5u);
    Pcg32 b = pixel_stream(10, 20, 5u);
    Pcg32 c = pixel_stream(20, 10, 5u);
    const uint32_t va = a.next_uint();
    EXPECT_EQ(va, b.next_uint());
    EXPECT_NE(va, c.next_uint());
}

}  // namespace
}  // namespace glintlab
