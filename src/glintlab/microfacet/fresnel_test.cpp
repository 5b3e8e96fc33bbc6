// Fresnel terms (fresnel.glsl): closed-form special cases of the exact equations.
#include <gtest/gtest.h>

#include <cmath>

#include "glintlab/microfacet/microfacet.h"

namespace glintlab {
namespace {

using namespace shader;

TEST(MicrofacetFresnel, DielectricNormalIncidence) {
    for (float eta : {1.0f, 1.33f, 1.5f, 2.4f, 0.6667f}) {
        const float r = (eta - 1.0f) / (eta + 1.0f);
        // Float evaluation of the same quotients: a few ulp.
        EXPECT_NEAR(F_Dielectric(1.0f, eta), r * r, 1e-6f) << eta;
        // From inside (cos < 0) the ratio inverts; at normal incidence R is symmetric.
        EXPECT_NEAR(F_Dielectric(-1.0f, eta), r * r, 1e-6f) << eta;
    }
}

TEST(MicrofacetFresnel, DielectricTotalInternalReflection) {
    const float eta = 1.5f;
    const float critical = std::sqrt(1.0f - 1.0f / (eta * eta));  // cos of the critical angle
    EXPECT_EQ(F_Dielectric(-(critical - 0.01f), eta), 1.0f);
    EXPECT_EQ(F_Dielectric(-0.0f, eta), 1.0f);
    EXPECT_LT(F_Dielectric(-(critical + 0.01f), eta), 1.0f);
    // Going in from outside at grazing incidence never totally reflects but tends to 1.
    EXPECT_GT(F_Dielectric(1e-4f, eta), 0.99f);
}

TEST(MicrofacetFresnel, DielectricIsSymmetricUnderSnell) {
    // Stokes relation: R is the same for the pair of angles linked by Snell's law.
    const float eta = 1.5f;
    for (float cos_i : {0.2f, 0.5f, 0.9f}) {
        const float sin_t = std::sqrt(1.0f - cos_i * cos_i) / eta;
        const float cos_t = std::sqrt(1.0f - sin_t * sin_t);
        EXPECT_NEAR(F_Dielectric(cos_i, eta), F_Dielectric(-cos_t, eta), 2e-6f) << cos_i;
    }
}

TEST(MicrofacetFresnel, ConductorWithoutAbsorptionIsDielectric) {
    for (float eta : {1.2f, 1.5f, 2.5f})
        for (int i = 0; i <= 100; ++i) {
            const float c = float(i) / 100.0f;
            // Different algebra for the same quantity: float rounding of O(10) ops.
            EXPECT_NEAR(F_ConductorScalar(c, eta, 0.0f), F_Dielectric(c, eta), 2e-6f)
                << "eta " << eta << " cos " << c;
        }
}

TEST(MicrofacetFresnel, ConductorNormalIncidenceAndGrazing) {
    // At normal incidence R = ((eta-1)^2 + k^2) / ((eta+1)^2 + k^2).
    const glm::vec3 eta(0.2f, 0.9f, 1.1f), k(3.9f, 2.4f, 2.3f);
    const glm::vec3 F = F_Conductor(1.0f, eta, k);
    for (int c = 0; c < 3; ++c) {
        const float ref = ((eta[c] - 1) * (eta[c] - 1) + k[c] * k[c]) /
                          ((eta[c] + 1) * (eta[c] + 1) + k[c] * k[c]);
        EXPECT_NEAR(F[c], ref, 1e-6f);
    }
    const glm::vec3 G = F_Conductor(0.0f, eta, k);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(G[c], 1.0f, 1e-6f);
}

// eta = 1, k = 0 is no interface: F = 0 at every angle. The numerators
// cancel there, and unclamped rounding gives F ~ -1e-8, which renders as
// negative pixels. Never negative, and 0 to fp32 rounding of the cancellation.
TEST(MicrofacetFresnel, ConductorWithoutInterfaceIsZeroNeverNegative) {
    for (int i = 0; i <= 100000; ++i) {
        const float c = static_cast<float>(i) / 100000.0f;
        const float f = F_ConductorScalar(c, 1.0f, 0.0f);
        ASSERT_GE(f, 0.0f) << "cos " << c;
        ASSERT_LT(f, 1e-6f) << "cos " << c;
    }
    for (int i = 0; i <= 1000; ++i) {
        const float c = static_cast<float>(i) / 1000.0f;
        for (float eta : {0.05f, 0.5f, 1.0f, 1.0001f, 2.0f, 8.0f})
            for (float k : {0.0f, 1e-4f, 0.5f, 4.0f}) ASSERT_GE(F_ConductorScalar(c, eta, k), 0.0f);
    }
}

TEST(MicrofacetFresnel, SchlickEndpoints) {
    EXPECT_FLOAT_EQ(F_Schlick(0.04f, 1.0f), 0.04f);
    EXPECT_FLOAT_EQ(F_Schlick(0.04f, 0.0f), 1.0f);
    const glm::vec3 F0(0.9f, 0.6f, 0.3f);
    const glm::vec3 F = F_Schlick(F0, 1.0f);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(F[c], F0[c]);
}

}  // namespace
}  // namespace glintlab
