// Environment map lookups and importance sampling.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "glintlab/core/rng.h"
#include "glintlab/scene/environment.h"

namespace glintlab {
namespace {

// A 64x32 map: dim background, one very bright texel block, a coloured band.
Image test_map() {
    Image img(64, 32, glm::vec3(0.05f));
    for (int y = 5; y < 8; ++y)
        for (int x = 40; x < 43; ++x) img.at(x, y) = glm::vec3(200.0f, 150.0f, 100.0f);
    for (int x = 0; x < 64; ++x) img.at(x, 20) = glm::vec3(0.0f, 2.0f, 0.5f);
    return img;
}

// ∫ f(ω) dω over the sphere by the midpoint rule on a fine (θ, φ) grid.
template <typename F>
double sphere_integral(F f, int n_theta = 1024, int n_phi = 2048) {
    double sum = 0.0;
    for (int i = 0; i < n_theta; ++i) {
        const double theta = glm::pi<double>() * (i + 0.5) / n_theta;
        for (int j = 0; j < n_phi; ++j) {
            const double phi = 2.0 * glm::pi<double>() * (j + 0.5) / n_phi;
            const glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            sum += f(d) * std::sin(theta);
        }
    }
    return sum * (glm::pi<double>() / n_theta) * (2.0 * glm::pi<double>() / n_phi);
}

TEST(Environment, UvMappingRoundTripsWithRotation) {
    const EnvironmentMap env(test_map(), 1.0f, 37.0f);
    Pcg32 rng(3u, 4u);
    for (int i = 0; i < 1000; ++i) {
        const glm::vec2 uv(rng.next_float(), 0.01f + 0.98f * rng.next_float());
        const glm::vec2 back = env.direction_to_uv(env.uv_to_direction(uv));
        EXPECT_NEAR(std::fmod(back.x - uv.x + 1.5f, 1.0f) - 0.5f, 0.0f, 1e-5f);
        EXPECT_NEAR(back.y, uv.y, 1e-5f);
    }
    // Documented convention: u = 0.5 looks along −z, the top row is +y.
    const EnvironmentMap plain(test_map(), 1.0f, 0.0f);
    EXPECT_NEAR(plain.direction_to_uv(glm::vec3(0, 0, -1)).x, 0.5f, 1e-6f);
    EXPECT_NEAR(plain.direction_to_uv(glm::vec3(1, 0, 0)).x, 0.75f, 1e-6f);
    EXPECT_NEAR(plain.direction_to_uv(glm::vec3(0, 1, 0)).y, 0.0f, 1e-6f);
}

TEST(Environment, PdfIntegratesToOne) {
    const EnvironmentMap env(test_map(), 1.0f, 10.0f);
    // Midpoint quadrature of a piecewise-constant density with 64x32 cells on
    // a 2048x1024 grid: error from cells straddling grid lines ~1e-3.
    EXPECT_NEAR(sphere_integral([&](glm::vec3 d) { return env.pdf(d); }), 1.0, 3e-3);
}

TEST(Environment, SamplesAgreeWithPdfAndEstimateTheIntegral) {
    const EnvironmentMap env(test_map(), 2.0f, -25.0f);
    const double reference = sphere_integral([&](glm::vec3 d) { return double(env.eval(d).x); });
    Pcg32 rng(11u, 5u);
    const int n = 200000;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        glm::vec3 dir;
        float pdf = 0.0f;
        const glm::vec3 L = env.sample({rng.next_float(), rng.next_float()}, &dir, &pdf);
        ASSERT_GT(pdf, 0.0f);
        ASSERT_NEAR(glm::length(dir), 1.0f, 1e-5f);
        // pdf() must return the density sample() used (MIS needs both to agree).
        ASSERT_NEAR(env.pdf(dir), pdf, 2e-3f * pdf);
        const double v = L.x / pdf;
        sum += v, sum2 += v * v;
    }
    const double mean = sum / n;
    const double sigma = std::sqrt((sum2 / n - mean * mean) / n);
    // Unbiased estimator: within 5σ (plus the quadrature's 1e-3 relative error).
    EXPECT_NEAR(mean, reference, 5.0 * sigma + 2e-3 * reference);
    // Importance sampling must beat uniform sphere sampling by far on this
    // map (dominated by a small bright block): uniform sampling has variance
    // 4π∫L² − (∫L)²; require at least a 3x smaller standard deviation.
    const double second =
        sphere_integral([&](glm::vec3 d) { return double(env.eval(d).x) * env.eval(d).x; });
    const double uniform_sigma =
        std::sqrt(4.0 * glm::pi<double>() * second - reference * reference);
    EXPECT_LT(sigma * std::sqrt(double(n)), uniform_sigma / 3.0);
}

TEST(Environment, ConstantMapIsNearlyUniform) {
    const EnvironmentMap env = EnvironmentMap::constant(glm::vec3(0.25f, 0.5f, 1.0f));
    EXPECT_NEAR(env.eval(glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f))).y, 0.5f, 1e-6f);
    // The sampling density is constant per grid row of height Δθ = π/64 and
    // ∝ sinθ_row / sinθ within it, so its relative deviation from 1/4π is at
    // most (Δθ/2)|cot θ| to first order, plus (Δθ)²/8 where cot θ vanishes
    // and (Δθ)²/24 from the midpoint-rule normalisation of the marginal.
    for (float theta_deg : {20.0f, 45.0f, 80.0f, 90.0f, 120.0f, 170.0f}) {
        const float t = glm::radians(theta_deg);
        const glm::vec3 d(std::sin(t) * 0.6f, std::cos(t), std::sin(t) * 0.8f);
        const float dtheta = glm::pi<float>() / 64.0f;
        const float bound =
            0.5f * dtheta * std::abs(std::cos(t) / std::sin(t)) + dtheta * dtheta / 6.0f;
        EXPECT_NEAR(env.pdf(d) * 4.0f * glm::pi<float>(), 1.0f, 1.05f * bound) << theta_deg;
    }
}

}  // namespace
}  // namespace glintlab
