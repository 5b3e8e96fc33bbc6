// The GPU glue's early exits of deliot2023 (deliot2023.glsl
// deliot2023_expectation_exit) against the full evaluation they
// replace, on the CPU: this file compiles the shared source with
// GLINTLAB_DELIOT2023_EXPECTATION_EXITS, as the GPU glue does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "glintlab/core/glsl.h"
#include "glintlab/core/rng.h"

#define GLINTLAB_DELIOT2023_EXPECTATION_EXITS 1
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/deliot2023/deliot2023.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

using namespace shader;

// D_P without the exits (deliot2023_ndf's body after the exit).
float full_ndf(glm::vec3 h, const Footprint& fp, float alpha, float log_density, uint32_t seed,
               float R, float randomization) {
    const float d_h = D_Microfacet(NDF_BECKMANN, h, alpha, alpha);
    const float d_n = D_Microfacet(NDF_BECKMANN, glm::vec3(0, 0, 1), alpha, alpha);
    const float p = glm::clamp(R * d_h / d_n, 0.0f, 1.0f);
    const Deliot2023Grids g = deliot2023_footprint_grids(fp, 1.0f, false);
    glm::vec2 acc(0.0f);
    for (int i = 0; i < 4; ++i) {
        if (g.weight[i] <= 0.0f) continue;
        acc += deliot2023_grid_counts(deliot2023_grid_id(g, i), g.weight[i], fp.uv,
                                      glm::vec2(h.x, h.y) / R, p, log_density, seed, randomization,
                                      false, true);
    }
    return acc.y > 0.0f ? d_n / R * (acc.x / acc.y) : d_h;
}

// Random half vectors (Beckmann alpha 0.3: p from 1 down to far below
// 1e-30), footprints of 1e-6 to 1e-1 uv with anisotropy up to 64, log
// densities -10 to 60, density jitter 0 or 1. Where an exit is taken:
//  (a) (sum of N p < 2^-24): the full evaluation's counts are all 0 except
//      with probability <= 48 x 2^-24 per query (the fp32 gate's uniform
//      grid), so among the exit-(a) queries (about 10^4 here, expected
//      non-zero < 0.03 in all) at most 2 may be non-zero (measured 0 of
//      21433);
//  (b) (every vertex N p > 2^48): the full value is D(h) within 5.3
//      standard deviations of 2^-24 relative per count plus fp32 rounding of
//      the sums: limit 2e-6 relative (measured 2.3e-7).
// Both exits must be taken on some queries (the test is not vacuous), and
// deliot2023_ndf returns 0 at (a) and D(h) at (b).
TEST(Deliot2023Exits, ExpectationExitsAgreeWithTheFullEvaluation) {
    Pcg32 rng(17u, 5u);
    const float alpha = 0.3f;
    int exits_a = 0, exits_b = 0, nonzero_a = 0;
    double worst_b = 0.0;
    for (int q = 0; q < 40000; ++q) {
        const float tan_t = 3.0f * rng.next_float();
        const float phi = 6.2831853f * rng.next_float();
        const glm::vec3 h =
            glm::normalize(glm::vec3(tan_t * std::cos(phi), tan_t * std::sin(phi), 1.0f));
        Footprint fp;
        fp.uv = glm::vec2(rng.next_float(), rng.next_float()) * 10.0f;
        const float size = std::pow(10.0f, -6.0f + 5.0f * rng.next_float());
        const float aniso = std::pow(64.0f, rng.next_float());
        const float rot = 3.14159265f * rng.next_float();
        fp.duvdx = size * glm::vec2(std::cos(rot), std::sin(rot));
        fp.duvdy = size / aniso * glm::vec2(-std::sin(rot), std::cos(rot));
        const float log_density = -10.0f + 70.0f * rng.next_float();
        const float jitter = rng.next_float() < 0.5f ? 0.0f : 1.0f;
        const uint32_t seed = rng.next_uint();
        const float R = 0.5f;
        const float d_h = D_Microfacet(NDF_BECKMANN, h, alpha, alpha);
        const float d_n = D_Microfacet(NDF_BECKMANN, glm::vec3(0, 0, 1), alpha, alpha);
        const float p = glm::clamp(R * d_h / d_n, 0.0f, 1.0f);
        if (!(d_h > 0.0f)) continue;
        const Deliot2023Grids g = deliot2023_footprint_grids(fp, 1.0f, false);
        const int exit_kind = deliot2023_expectation_exit(g, p, log_density, jitter);
        if (exit_kind == DELIOT2023_NO_EXIT) continue;
        const float exited = deliot2023_ndf(h, fp, NDF_BECKMANN, alpha, alpha, 0.0f, log_density,
                                            seed, R, 1.0f, jitter, false, true);
        ASSERT_EQ(exited, exit_kind == DELIOT2023_EXIT_ZERO ? 0.0f : d_h);
        const float full = full_ndf(h, fp, alpha, log_density, seed, R, jitter);
        // Which exit: (a) has far fewer than one expected success.
        float most = 0.0f;
        for (int i = 0; i < 4; ++i)
            if (g.weight[i] > 0.0f)
                most += 3.0f * std::exp(glm::clamp(log_density + std::log(g.weight[i]) +
                                                       float(2 * deliot2023_grid_id(g, i).x +
                                                             deliot2023_grid_id(g, i).y) *
                                                           DELIOT2023_LN2 +
                                                       jitter * DELIOT2023_MAX_JITTER_Z,
                                                   -80.0f, 80.0f));
        if (most * p < 5.9604645e-8f) {
            ++exits_a;
            if (full != 0.0f) ++nonzero_a;
        } else {
            ++exits_b;
            worst_b = std::max(worst_b, std::abs(double(full) / double(d_h) - 1.0));
        }
    }
    RecordProperty("exits_a", exits_a);
    RecordProperty("exits_b", exits_b);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", worst_b);
    RecordProperty("worst_b", buf);
    EXPECT_GT(exits_a, 1000);
    EXPECT_GT(exits_b, 100);
    EXPECT_LE(nonzero_a, 2);
    EXPECT_LT(worst_b, 2e-6);
}

}  // namespace
}  // namespace glintlab
