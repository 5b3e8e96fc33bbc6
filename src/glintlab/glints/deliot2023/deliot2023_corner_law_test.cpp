// deliot2023_vertex_count draws its 4 corners' counts with one normal
// quantile per corner for every law (a SIMD back end would run the shipped
// law and the fixed one side by side). This checks that the counts
// are, bit for bit, those of the laws as written: the shipped law below
// for `original_defects`, binomial_single_gated_draw of the single-gated
// (003 Eq. 23) or conditional law otherwise, blended as Eq. 14 blends them.
#include <gtest/gtest.h>

#include <cmath>

#include "glintlab/core/glsl.h"
#include "glintlab/core/rng.h"

GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/deliot2023/deliot2023.glsl"

// The original HLSL's gated Gaussian (000 Eq. 16-18 as shipped), written as
// a function of its own: naive fp32
// (1 - p)^N, the gate 1 - (1 - p)^N also for N < 1, and the Gaussian for the
// N - 1 remaining trials clamped to N instead of N - 1.
float deliot2023_original_law(float N, float p, float xi0, float xi1) {
    float p_any = 1.0f - pow_one_minus_naive(p, N);  // Eq. 16
    float rest = max(N - 1.0f, 0.0f);                // Eq. 17
    float g = clamp(gaussian_deviate(rest * p, rest * p * (1.0f - p), xi1), 0.0f, N);
    return xi0 < p_any ? floor(1.0f + g) : 0.0f;  // Eq. 18
}
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

using namespace shader;

// Eq. 14 over the 4 corners with one law call per corner (the laws as
// written, one quantile per law call).
float vertex_count_per_corner_law(float N, glm::vec2 angular_offset, uint vs, glm::vec2 slope,
                                  float p, bool original_defects, bool conditional) {
    glm::vec2 a = glm::mod(slope + angular_offset, DELIOT2023_LATTICE_PERIOD);
    const glm::vec2 af = glm::floor(a);
    const glm::ivec2 ac(af);
    const glm::vec2 at = glm::clamp(a - af, 0.0f, 1.0f);
    const SingleGatedLaw law =
        conditional ? binomial_single_gated_conditional_law(N, p) : binomial_single_gated_law(N, p);
    float count = 0.0f;
    for (int c = 0; c < 4; ++c) {
        const glm::ivec2 corner = ac + glm::ivec2(c & 1, c >> 1);
        const float wc = ((c & 1) == 1 ? at.x : 1.0f - at.x) * ((c >> 1) == 1 ? at.y : 1.0f - at.y);
        const glm::vec2 xi =
            deliot2023_corner_uniforms(corner & glm::ivec2(DELIOT2023_LATTICE_MASK), vs);
        const float b = original_defects ? deliot2023_original_law(N, p, xi.x, xi.y)
                                         : binomial_single_gated_draw(law, xi.x, xi.y);
        count += wc * b;
    }
    return count;
}

TEST(Deliot2023CornerLaw, OneQuantilePerCornerGivesTheLawsCounts) {
    // N log-uniform over [1e-3, 1e12] (below one trial, where the gate's
    // N < 1 form differs between the laws, to the Gaussian regime), p
    // log-uniform over [1e-9, 1] (closed gates to sure ones).
    Pcg32 rng(17, 3);
    int non_zero[3] = {0, 0, 0};
    for (int k = 0; k < 20000; ++k) {
        const float N = std::pow(10.0f, -3.0f + 15.0f * rng.next_float());
        const float p = std::pow(10.0f, -9.0f * rng.next_float());
        const glm::vec2 offset(rng.next_float(), rng.next_float());
        const uint vs = rng.next_uint();
        const glm::vec2 slope(40.0f * (rng.next_float() - 0.5f), 40.0f * (rng.next_float() - 0.5f));
        for (int variant = 0; variant < 3; ++variant) {
            const bool original = variant == 0;
            const bool conditional = variant == 2;
            const float expected =
                vertex_count_per_corner_law(N, offset, vs, slope, p, original, conditional);
            const float got =
                deliot2023_vertex_count(N, offset, vs, slope, p, original, conditional);
            ASSERT_EQ(got, expected) << "N " << N << " p " << p << " variant " << variant;
            non_zero[variant] += expected > 0.0f;
        }
    }
    // The gates open in a good share of the draws for every law, so the
    // Gaussian parts are compared too, not only closed gates' zeros.
    for (int variant = 0; variant < 3; ++variant) EXPECT_GE(non_zero[variant], 4000) << variant;
}

}  // namespace
}  // namespace glintlab
