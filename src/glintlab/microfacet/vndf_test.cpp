// Visible-normal sampling (vndf.glsl) against its density, Pearson chi-square.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "glintlab/microfacet/chi2_test_util.h"
#include "glintlab/microfacet/microfacet.h"

namespace glintlab {
namespace {

using namespace shader;

struct VndfCase {
    int ndf;
    float ax, ay;
    float theta_deg, phi_deg;
};

// Both NDFs x {rough iso, smooth iso, anisotropic} x {normal, 45 deg, 80 deg}.
std::vector<VndfCase> vndf_cases() {
    std::vector<VndfCase> cases;
    for (int ndf : {NDF_BECKMANN, NDF_GGX})
        for (auto [ax, ay] : {std::pair{0.6f, 0.6f}, {0.15f, 0.15f}, {0.1f, 0.5f}})
            for (auto [t, p] : {std::pair{0.0f, 0.0f}, {45.0f, 30.0f}, {80.0f, 200.0f}})
                cases.push_back({ndf, ax, ay, t, p});
    return cases;
}

TEST(MicrofacetVndf, ChiSquareAgainstPdf) {
    const std::vector<VndfCase> cases = vndf_cases();
    // 1% family-wise false-failure rate over all cases (Sidak).
    const double significance = testing::sidak_significance(0.01, int(cases.size()));
    uint64_t seed = 7;
    for (const VndfCase& c : cases) {
        const float t = c.theta_deg * std::numbers::pi_v<float> / 180.0f;
        const float p = c.phi_deg * std::numbers::pi_v<float> / 180.0f;
        const glm::vec3 wo(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
        testing::Chi2Config cfg;
        cfg.full_sphere = false;  // visible normals are in the upper hemisphere
        cfg.seed = seed++;
        const auto r =
            testing::chi2_test([&](glm::vec3 m) { return pdf_vndf(c.ndf, wo, m, c.ax, c.ay); },
                               [&](Pcg32& rng) -> std::optional<glm::vec3> {
                                   const glm::vec2 u(rng.next_float(), rng.next_float());
                                   return sample_vndf(c.ndf, wo, c.ax, c.ay, u);
                               },
                               cfg);
        const auto what = fmt::format("ndf {} alpha ({}, {}) wo ({}, {}) deg: {}", c.ndf, c.ax,
                                      c.ay, c.theta_deg, c.phi_deg, r.describe());
        EXPECT_GT(r.p_value, significance) << what;
        // The visible NDF is a density: its integral over the hemisphere is 1
        // (weak furnace); the adaptive quadrature reaches ~1e-5.
        EXPECT_NEAR(r.pdf_mass, 1.0, 1e-4) << what;
        EXPECT_EQ(r.accepted, cfg.samples) << what;
    }
}

TEST(MicrofacetVndf, SamplesAreUnitAndVisible) {
    Pcg32 rng(3, 4);
    for (int ndf : {NDF_BECKMANN, NDF_GGX})
        for (int i = 0; i < 20000; ++i) {
            const glm::vec3 wo = glm::normalize(glm::vec3(
                rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() + 1e-3f));
            const glm::vec2 u(rng.next_float(), rng.next_float());
            const glm::vec3 m = sample_vndf(ndf, wo, 0.3f, 0.05f, u);
            ASSERT_NEAR(glm::length(m), 1.0f, 1e-5f);
            ASSERT_GE(m.z, 0.0f);
            // Back-facing visible normals have zero density; allow rounding at the
            // silhouette where wo.m ~ 0.
            ASSERT_GT(glm::dot(wo, m), -1e-4f);
        }
}

}  // namespace
}  // namespace glintlab
