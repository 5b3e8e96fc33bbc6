// CPU BxDFs (bxdfs.h): sample() agrees with f() and pdf(), sampling matches the
// pdf (chi-square), reciprocity, energy conservation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "glintlab/microfacet/bxdfs.h"
#include "glintlab/microfacet/chi2_test_util.h"
#include "glintlab/microfacet/microfacet.h"

namespace glintlab {
namespace {

struct NamedBxdf {
    std::string name;
    Bxdf bxdf;
    bool two_sided_wo;  // wo may come from below (dielectric interfaces)
};

// Rough (non-delta) configurations covering both NDFs and anisotropy.
std::vector<NamedBxdf> rough_bxdfs() {
    const MicrofacetDistribution ggx{NdfType::GGX, 0.3f, 0.3f};
    const MicrofacetDistribution beck_aniso{NdfType::Beckmann, 0.2f, 0.45f};
    const MicrofacetDistribution ggx_aniso{NdfType::GGX, 0.5f, 0.15f};
    return {
        {"diffuse", DiffuseBxdf{glm::vec3(0.8f, 0.5f, 0.2f)}, false},
        {"conductor ggx",
         ConductorBxdf{ggx, glm::vec3(0.2f, 0.9f, 1.1f), glm::vec3(3.9f, 2.4f, 2.3f)}, false},
        {"conductor beckmann aniso",
         ConductorBxdf{beck_aniso, glm::vec3(0.2f, 0.9f, 1.1f), glm::vec3(3.9f, 2.4f, 2.3f)},
         false},
        {"dielectric ggx", DielectricBxdf{ggx, 1.5f}, true},
        {"dielectric beckmann aniso", DielectricBxdf{beck_aniso, 1.33f}, true},
        {"plastic ggx aniso", PlasticBxdf{glm::vec3(0.7f, 0.4f, 0.3f), ggx_aniso, 1.5f}, false},
        {"plastic beckmann", PlasticBxdf{glm::vec3(0.7f, 0.4f, 0.3f), beck_aniso, 1.5f}, false},
        {"metallic-roughness 0.4 ggx aniso",
         MetallicRoughnessBxdf{glm::vec3(0.9f, 0.6f, 0.2f), 0.4f, ggx_aniso, 1.5f}, false},
        {"metallic-roughness 1 beckmann",
         MetallicRoughnessBxdf{glm::vec3(0.9f, 0.6f, 0.2f), 1.0f, beck_aniso, 1.5f}, false},
        {"metallic-roughness 0 ggx", MetallicRoughnessBxdf{glm::vec3(0.3f), 0.0f, ggx, 1.5f},
         false},
    };
}

glm::vec3 random_direction(Pcg32& rng, bool upper_only) {
    const float z = upper_only ? rng.next_float() : 2.0f * rng.next_float() - 1.0f;
    const float phi = 2.0f * std::numbers::pi_v<float> * rng.next_float();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

bool close_rel(float a, float b, float rel) {
    return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b));
}

TEST(MicrofacetBxdf, SampleAgreesWithEvalAndPdf) {
    Pcg32 rng(11, 12);
    for (const NamedBxdf& nb : rough_bxdfs()) {
        int checked = 0;
        for (int i = 0; i < 20000; ++i) {
            const glm::vec3 wo = random_direction(rng, !nb.two_sided_wo);
            if (std::abs(wo.z) < 1e-3f) continue;
            const auto s = bxdf_sample(nb.bxdf, wo, rng.next_float(),
                                       glm::vec2(rng.next_float(), rng.next_float()));
            if (!s) continue;
            ASSERT_FALSE(s->is_delta) << nb.name;
            ++checked;
            const glm::vec3 f = bxdf_f(nb.bxdf, wo, s->wi);
            const float p = bxdf_pdf(nb.bxdf, wo, s->wi);
            // Relative 1e-4 (the brief's bound; float rounding of the recomputed
            // half vector stays ~1e-6).
            ASSERT_TRUE(close_rel(s->pdf, p, 1e-4f)) << nb.name << " " << s->pdf << " vs " << p;
            for (int c = 0; c < 3; ++c)
                ASSERT_TRUE(close_rel(s->f[c], f[c], 1e-4f))
                    << nb.name << " " << s->f[c] << " vs " << f[c];
            ASSERT_GT(s->pdf, 0.0f);
            ASSERT_EQ(s->is_transmission, wo.z * s->wi.z < 0.0f) << nb.name;
        }
        EXPECT_GT(checked, 10000) << nb.name;  // sampling rarely fails for these lobes
    }
}

TEST(MicrofacetBxdf, ReflectionIsReciprocal) {
    Pcg32 rng(21, 22);
    for (const NamedBxdf& nb : rough_bxdfs())
        for (int i = 0; i < 5000; ++i) {
            const glm::vec3 wo = random_direction(rng, true), wi = random_direction(rng, true);
            const glm::vec3 a = bxdf_f(nb.bxdf, wo, wi), b = bxdf_f(nb.bxdf, wi, wo);
            // Helmholtz reciprocity of reflection; the dielectric's reflection lobe
            // is symmetric too. Float rounding: 1e-5 relative.
            for (int c = 0; c < 3; ++c)
                ASSERT_TRUE(close_rel(a[c], b[c], 1e-5f) || std::abs(a[c] - b[c]) < 1e-12f)
                    << nb.name << ": " << a[c] << " vs " << b[c];
        }
}

TEST(MicrofacetBxdf, DielectricTransmissionGeneralisedReciprocity) {
    // Radiance-mode BTDF: f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2 (Veach 1997
    // §5.2, f(wo, wi) scattering light from wi to wo), with eta of the medium
    // each direction lies in: here eta_o = 1, eta_i = 1.5.
    const DielectricBxdf d{{NdfType::GGX, 0.3f, 0.3f}, 1.5f};
    Pcg32 rng(31, 32);
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 wo = random_direction(rng, true);
        glm::vec3 wi = random_direction(rng, true);
        wi.z = -wi.z;  // wo outside (eta 1), wi inside (eta 1.5)
        // Skip wi within a few degrees of the critical angle (wo grazing the
        // microfacet): there 1 - F(wo.m) and 1 - F(wi.m) both vanish and each side's
        // float cancellation dominates.
        const glm::vec3 wm = glm::normalize(1.5f * wi + wo);
        if (std::abs(glm::dot(wo, wm)) < 0.05f) continue;
        const float a = d.f(wo, wi).x, b = d.f(wi, wo).x / (1.5f * 1.5f);
        if (a == 0.0f && b == 0.0f) continue;
        ++checked;
        // 1e-3: the two sides rebuild the half vector from wi eta + wo and
        // wo / eta + wi, and evaluate F from opposite sides; float rounding
        // reaches ~2e-4 relative away from the critical angle.
        ASSERT_TRUE(close_rel(a, b, 1e-3f)) << a << " vs " << b;
    }
    EXPECT_GT(checked, 2000);
}

// Monte Carlo albedo rho(wo) = integral of f cos over the sphere, estimated with
// the BxDF's own sampling (deltas included); returns (mean, standard error).
std::pair<double, double> albedo(const Bxdf& b, glm::vec3 wo, int n, uint64_t seed,
                                 int channel = 0) {
    Pcg32 rng(seed, 99);
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const auto s =
            bxdf_sample(b, wo, rng.next_float(), glm::vec2(rng.next_float(), rng.next_float()));
        double v = 0.0;
        if (s && s->pdf > 0.0f) v = double(s->f[channel]) * std::abs(s->wi.z) / s->pdf;
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

TEST(MicrofacetBxdf, EnergyConservation) {
    // White (albedo 1) versions of every lobe: rho(wo) <= 1 up to 3 standard
    // errors of the estimate (a 0.13% one-sided false-failure rate per check).
    const MicrofacetDistribution ggx_rough{NdfType::GGX, 0.8f, 0.8f};
    const MicrofacetDistribution beck{NdfType::Beckmann, 0.3f, 0.1f};
    const std::vector<std::pair<std::string, Bxdf>> white = {
        {"diffuse", DiffuseBxdf{glm::vec3(1.0f)}},
        {"conductor F~1 ggx", ConductorBxdf{ggx_rough, glm::vec3(1.0f), glm::vec3(1000.0f)}},
        {"conductor F~1 beckmann", ConductorBxdf{beck, glm::vec3(1.0f), glm::vec3(1000.0f)}},
        {"dielectric ggx", DielectricBxdf{ggx_rough, 1.5f}},
        {"dielectric beckmann", DielectricBxdf{beck, 1.5f}},
        {"plastic ggx", PlasticBxdf{glm::vec3(1.0f), ggx_rough, 1.5f}},
        {"plastic beckmann", PlasticBxdf{glm::vec3(1.0f), beck, 1.5f}},
        {"plastic smooth", PlasticBxdf{glm::vec3(1.0f), {NdfType::GGX, 1e-4f, 1e-4f}, 1.5f}},
        {"dielectric smooth", DielectricBxdf{{NdfType::GGX, 1e-4f, 1e-4f}, 1.5f}},
        {"metallic-roughness 0.5 ggx", MetallicRoughnessBxdf{glm::vec3(1.0f), 0.5f, ggx_rough}},
        {"metallic-roughness 0.5 smooth",
         MetallicRoughnessBxdf{glm::vec3(1.0f), 0.5f, {NdfType::GGX, 1e-4f, 1e-4f}}},
        {"metallic-roughness 0 beckmann", MetallicRoughnessBxdf{glm::vec3(1.0f), 0.0f, beck}},
    };
    uint64_t seed = 1;
    for (const auto& [name, b] : white)
        for (float theta_deg : {0.0f, 40.0f, 75.0f, 88.0f}) {
            const float t = theta_deg * std::numbers::pi_v<float> / 180.0f;
            const glm::vec3 wo(std::sin(t), 0.0f, std::cos(t));
            const auto [mean, se] = albedo(b, wo, 100000, seed++);
            // 1e-5: float rounding of f cos / pdf when the estimator is exact (se = 0).
            EXPECT_LE(mean, 1.0 + 3.0 * se + 1e-5) << name << " theta " << theta_deg;
            // A smooth dielectric loses nothing: R + T = 1 exactly in radiance
            // units times 1/eta^2 for the transmitted part.
            if (name == "diffuse") {
                EXPECT_NEAR(mean, 1.0, 4.0 * se + 1e-6) << name;
            }
        }
}

TEST(MicrofacetBxdf, WhiteConductorLosesOnlyMultipleScattering) {
    // With F = 1 the single-scattering albedo is E_vis[G2 / G1 H(wi.z)] (Heitz
    // 2014 §6): 1 minus the energy of inter-reflections and of reflections
    // below the horizon. For Beckmann alpha = 0.1 at theta_o <= 60 deg both are
    // negligible (Lambda(60 deg) ~ exp(-33), P(tan theta_m > 0.58) = exp(-33)),
    // so rho > 0.999. (GGX alpha = 0.1 loses ~1% at normal incidence through
    // its heavy tail: about 1% of visible normals tilt past 45 deg.)
    // k = 1000 gives F > 1 - 2e-5 at every angle.
    const ConductorBxdf smooth_ish{
        {NdfType::Beckmann, 0.1f, 0.1f}, glm::vec3(1.0f), glm::vec3(1000.0f)};
    const ConductorBxdf rough{{NdfType::GGX, 1.0f, 1.0f}, glm::vec3(1.0f), glm::vec3(1000.0f)};
    for (float theta_deg : {0.0f, 30.0f, 60.0f}) {
        const float t = theta_deg * std::numbers::pi_v<float> / 180.0f;
        const glm::vec3 wo(std::sin(t), 0.0f, std::cos(t));
        const auto [m1, se1] = albedo(smooth_ish, wo, 100000, 5);
        EXPECT_GT(m1, 0.999) << theta_deg;
        EXPECT_LE(m1, 1.0 + 3.0 * se1 + 1e-5) << theta_deg;
        const auto [m2, se2] = albedo(rough, wo, 100000, 6);
        EXPECT_LT(m2 + 3.0 * se2, m1) << theta_deg;  // rougher loses more
    }
}

TEST(MicrofacetBxdf, IndexMatchedDielectricIsLossless) {
    // eta -> 1: almost nothing reflects and the refracted direction barely bends,
    // so R + T = 1 up to the Smith multiple-scattering loss of a smooth surface
    // (< 0.5% at alpha = 0.05, theta <= 60 deg).
    const DielectricBxdf d{{NdfType::GGX, 0.05f, 0.05f}, 1.0001f};
    for (float theta_deg : {0.0f, 30.0f, 60.0f}) {
        const float t = theta_deg * std::numbers::pi_v<float> / 180.0f;
        for (float sign : {1.0f, -1.0f}) {
            const glm::vec3 wo(std::sin(t), 0.0f, sign * std::cos(t));
            const auto [mean, se] = albedo(d, wo, 50000, 7);
            EXPECT_NEAR(mean, 1.0, 5e-3 + 3.0 * se) << theta_deg << " side " << sign;
        }
    }
}

TEST(MicrofacetBxdf, SmoothLimitIsDelta) {
    const MicrofacetDistribution smooth{NdfType::GGX, 1e-4f, 1e-4f};
    const ConductorBxdf c{smooth, glm::vec3(0.2f), glm::vec3(3.0f)};
    EXPECT_TRUE(c.is_specular());
    const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, 0.2f, 0.8f));
    const auto s = c.sample(wo, 0.5f, glm::vec2(0.3f));
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->is_delta);
    EXPECT_EQ(s->wi, glm::vec3(-wo.x, -wo.y, wo.z));
    EXPECT_EQ(c.f(wo, s->wi), glm::vec3(0.0f));  // deltas are not evaluable
    const DielectricBxdf d{smooth, 1.5f};
    const auto r = d.sample(wo, 0.0f, glm::vec2(0.5f)), t = d.sample(wo, 0.999f, glm::vec2(0.5f));
    ASSERT_TRUE(r && t);
    EXPECT_TRUE(r->is_delta && !r->is_transmission);
    EXPECT_TRUE(t->is_delta && t->is_transmission);
    EXPECT_NEAR(r->pdf + t->pdf, 1.0f, 1e-6f);
    // Snell: sin_t = sin_o / eta.
    EXPECT_NEAR(std::hypot(t->wi.x, t->wi.y), std::hypot(wo.x, wo.y) / 1.5f, 1e-6f);
}

// glTF's material at its ends: metallic 0 is the plastic, metallic 1 the
// Schlick metal D G2 F_Schlick(F0 = base colour) / (4 cos_o cos_i).
TEST(MicrofacetBxdf, MetallicRoughnessEndsAreThePlasticAndTheSchlickMetal) {
    const MicrofacetDistribution ggx{NdfType::GGX, 0.35f, 0.2f};
    const glm::vec3 base(0.9f, 0.6f, 0.2f);
    const MetallicRoughnessBxdf dielectric{base, 0.0f, ggx, 1.45f};
    const MetallicRoughnessBxdf metal{base, 1.0f, ggx, 1.45f};
    const PlasticBxdf plastic{base, ggx, 1.45f};
    Pcg32 rng(5, 6);
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 wo = random_direction(rng, true), wi = random_direction(rng, true);
        if (wo.z < 1e-2f || wi.z < 1e-2f) continue;
        const glm::vec3 fp = plastic.f(wo, wi), fd = dielectric.f(wo, wi);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(fd[c], fp[c], 1e-6f * std::max(1.0f, fp[c]));
        EXPECT_NEAR(dielectric.pdf(wo, wi), plastic.pdf(wo, wi),
                    1e-5f * std::max(1.0f, plastic.pdf(wo, wi)));
        const glm::vec3 wm = glm::normalize(wo + wi);
        const float m5 = std::pow(1.0f - glm::dot(wo, wm), 5.0f);
        const float dg = ggx.D(wm) * ggx.G2(wo, wi) / (4.0f * wo.z * wi.z);
        const glm::vec3 fm = metal.f(wo, wi);
        for (int c = 0; c < 3; ++c) {
            const float expected = dg * (base[c] + (1.0f - base[c]) * m5);
            EXPECT_NEAR(fm[c], expected, 1e-4f * std::max(1.0f, expected));
        }
    }
}

TEST(MicrofacetBxdf, SmoothMetallicRoughnessSumsBothMirrorLobes) {
    // Half metal (Schlick F0 = 0.8), half plastic (IOR 1.5): the mirror
    // direction carries 0.5 F_Schlick + 0.5 F_Dielectric, chosen with the
    // metal's probability plus the plastic's specular share; the rest of
    // the samples are the plastic's diffuse lobe.
    const MetallicRoughnessBxdf b{glm::vec3(0.8f), 0.5f, {NdfType::GGX, 1e-4f, 1e-4f}, 1.5f};
    EXPECT_FALSE(b.is_specular());
    const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, 0.2f, 0.8f));
    const auto s = b.sample(wo, 0.1f, glm::vec2(0.3f));
    ASSERT_TRUE(s);
    ASSERT_TRUE(s->is_delta);
    const float c = wo.z;
    const float m5 = std::pow(1.0f - c, 5.0f);
    const float schlick = 0.8f + 0.2f * m5;
    const float fresnel = shader::F_Dielectric(c, 1.5f);
    EXPECT_NEAR(s->f.x * c, 0.5f * schlick + 0.5f * fresnel, 1e-5f);
    PlasticBxdf plastic{glm::vec3(0.8f), {NdfType::GGX, 1e-4f, 1e-4f}, 1.5f};
    EXPECT_NEAR(s->pdf, 0.5f + 0.5f * plastic.specular_probability(wo), 1e-6f);
    const auto d = b.sample(wo, 0.999f, glm::vec2(0.3f, 0.6f));
    ASSERT_TRUE(d);
    EXPECT_FALSE(d->is_delta);
    EXPECT_NEAR(d->pdf, (1.0f - s->pdf) * d->wi.z / std::numbers::pi_v<float>, 1e-5f);
    // Fully metallic and smooth: a mirror.
    const MetallicRoughnessBxdf mirror{glm::vec3(0.8f), 1.0f, {NdfType::GGX, 1e-4f, 1e-4f}, 1.5f};
    EXPECT_TRUE(mirror.is_specular());
}

TEST(MicrofacetBxdf, ChiSquareSamplingMatchesPdf) {
    const std::vector<NamedBxdf> bxdfs = rough_bxdfs();
    const std::vector<float> thetas = {20.0f, 70.0f};
    int tests = 0;
    for (const NamedBxdf& nb : bxdfs) tests += int(thetas.size()) * (nb.two_sided_wo ? 2 : 1);
    const double significance = testing::sidak_significance(0.01, tests);
    uint64_t seed = 100;
    for (const NamedBxdf& nb : bxdfs)
        for (float theta_deg : thetas)
            for (float side : {1.0f, -1.0f}) {
                if (side < 0.0f && !nb.two_sided_wo) continue;
                const float t = theta_deg * std::numbers::pi_v<float> / 180.0f;
                const glm::vec3 wo(std::sin(t) * 0.8f, std::sin(t) * 0.6f, side * std::cos(t));
                testing::Chi2Config cfg;
                cfg.seed = seed++;
                cfg.samples = 500000;
                const auto r =
                    testing::chi2_test([&](glm::vec3 wi) { return bxdf_pdf(nb.bxdf, wo, wi); },
                                       [&](Pcg32& rng) -> std::optional<glm::vec3> {
                                           const float uc = rng.next_float();
                                           const glm::vec2 u(rng.next_float(), rng.next_float());
                                           const auto s = bxdf_sample(nb.bxdf, wo, uc, u);
                                           if (!s) return std::nullopt;
                                           return s->wi;
                                       },
                                       cfg);
                EXPECT_GT(r.p_value, significance) << nb.name << " theta " << theta_deg << " side "
                                                   << side << ": " << r.describe();
            }
}

}  // namespace
}  // namespace glintlab
