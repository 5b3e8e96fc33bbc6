// The uniforms of deliot2023's angular corners (deliot2023_corner_uniforms,
// one pcg3d of (corner, vertex stream)): uniform, and
// independent between the pair's two numbers, between neighbouring corners
// and between vertices. The gated law needs all three: the gate and the
// Gaussian of one corner share the pair, the bilinear blend of Eq. 14 mixes
// the 4 neighbouring corners of a vertex, and the 12 vertices of a footprint
// draw at the same corners with their own streams.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "glintlab/core/glsl.h"

GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/deliot2023/deliot2023.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

using namespace shader;

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    const double n = double(a.size());
    double ma = 0.0, mb = 0.0;
    for (size_t i = 0; i < a.size(); ++i) ma += a[i] / n, mb += b[i] / n;
    double sab = 0.0, saa = 0.0, sbb = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / std::sqrt(saa * sbb);
}

// Over a 256 x 256 block of corners (the lattice's small coordinates, where
// a weak hash shows its structure) for 4 vertex streams (vs from the
// vertex's pcg_hash stream, as deliot2023_grid_counts draws them), n = 2^18
// pairs:
//  - each coordinate's histogram of 64 bins against uniform: Pearson chi^2
//    with 63 degrees of freedom, below 120 (p ~ 1e-5 for a uniform source);
//  - correlations of (xi.x, xi.y), of xi.x between horizontal and between
//    vertical neighbours, and of xi.y between streams at the same corner:
//    |r| <= 5 / sqrt(n) ~ 0.0098 (5 standard deviations of r under
//    independence, P ~ 6e-7 each).
TEST(Deliot2023, CornerUniformsAreUniformAndIndependent) {
    constexpr int kSide = 256;
    constexpr int kStreams = 4;
    std::array<uint, kStreams> vs{};
    uint state = 12345u;
    for (uint& v : vs) v = state = pcg_hash(state);
    std::vector<double> x, y, x_right, x_up, y_next_stream;
    std::array<std::vector<int>, 2> bins{std::vector<int>(64, 0), std::vector<int>(64, 0)};
    for (int s = 0; s < kStreams; ++s) {
        for (int j = 0; j < kSide; ++j) {
            for (int i = 0; i < kSide; ++i) {
                const glm::vec2 xi = deliot2023_corner_uniforms(glm::ivec2(i, j), vs[s]);
                ASSERT_GE(xi.x, 0.0f);
                ASSERT_LT(xi.x, 1.0f);
                ASSERT_GE(xi.y, 0.0f);
                ASSERT_LT(xi.y, 1.0f);
                ++bins[0][int(xi.x * 64.0f)];
                ++bins[1][int(xi.y * 64.0f)];
                x.push_back(xi.x);
                y.push_back(xi.y);
                x_right.push_back(deliot2023_corner_uniforms(glm::ivec2(i + 1, j), vs[s]).x);
                x_up.push_back(deliot2023_corner_uniforms(glm::ivec2(i, j + 1), vs[s]).x);
                y_next_stream.push_back(
                    deliot2023_corner_uniforms(glm::ivec2(i, j), vs[(s + 1) % kStreams]).y);
            }
        }
    }
    const double n = double(x.size());
    for (const std::vector<int>& b : bins) {
        double chi2 = 0.0;
        for (int c : b) chi2 += (c - n / 64.0) * (c - n / 64.0) / (n / 64.0);
        EXPECT_LT(chi2, 120.0);
    }
    const double bound = 5.0 / std::sqrt(n);
    EXPECT_LT(std::abs(correlation(x, y)), bound) << "the pair's two numbers";
    EXPECT_LT(std::abs(correlation(x, x_right)), bound) << "horizontal neighbours";
    EXPECT_LT(std::abs(correlation(x, x_up)), bound) << "vertical neighbours";
    EXPECT_LT(std::abs(correlation(y, y_next_stream)), bound) << "two vertices' streams";
}

}  // namespace
}  // namespace glintlab
