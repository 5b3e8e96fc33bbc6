// Regression test of wang2020's counting quotients: a footprint of area ~0
// (zero, or ~1e-32 uv² with the rare reflection probability of roughness
// 0.02) made sigma * area * N * phat underflow to 0, and 0 / 0 gave NaN
// pixels (found by `glintlab validate robustness`).
#include <gtest/gtest.h>

#include <cmath>

#include "glintlab/core/glsl.h"

GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/wang2020/wang2020.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

TEST(Wang2020Overflow, CountQuotientsAreFiniteForVanishingFootprints) {
    const glm::vec3 lhat(2.0f, 1.0f, 0.5f);
    for (const float area : {0.0f, 1e-45f, 9e-32f}) {
        for (const float phat : {1e-12f, 1e-3f}) {
            const glm::vec3 micro = shader::wang2020_environment_combine(
                shader::WANG2020_MICRO, lhat, phat, 0.0f, 0.0f, area, 1.0f, 0.5f);
            const glm::vec3 meso = shader::wang2020_environment_combine(
                shader::WANG2020_MESO, lhat, phat, 0.0f, 0.0f, area, 1.0f, 0.5f);
            EXPECT_TRUE(std::isfinite(micro.x) && std::isfinite(meso.x)) << area << " " << phat;
            EXPECT_TRUE(std::isfinite(shader::wang2020_point_dprime(shader::WANG2020_MICRO, phat,
                                                                    0.0f, 0.0f, area, 1.0f, 0.5f)));
            EXPECT_TRUE(std::isfinite(shader::wang2020_point_dprime(shader::WANG2020_MESO, phat,
                                                                    0.0f, 0.0f, area, 1.0f, 0.5f)));
        }
    }
    // Where the denominator is a normal float the quotient is the plain one.
    const float area = 1e-4f, total = 1e6f, sigma = 0.3f, phat = 0.01f;
    EXPECT_EQ(shader::wang2020_environment_combine(shader::WANG2020_MICRO, lhat, phat, 0.0f, 3.0f,
                                                   area, total, sigma),
              lhat * (3.0f / (sigma * area * total * phat)));
    EXPECT_EQ(
        shader::wang2020_point_dprime(shader::WANG2020_MESO, phat, 7.0f, 0.0f, area, total, sigma),
        7.0f * phat / (total * area * sigma));
}

}  // namespace
}  // namespace glintlab
