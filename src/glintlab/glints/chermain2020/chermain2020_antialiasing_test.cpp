// Chermain et al. 2021's geometric glint anti-aliasing in chermain2020: the
// box filter of the marginals, the half vector's slope differentials it is
// driven by, and what the two together approximate (the pixel's mean of D_P
// over the half vector's sweep).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "glintlab/core/glsl.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/chermain2020/chermain2020.h"
#include "glintlab/glints/chermain2020/dictionary.h"
#include "glintlab/glints/glint_desc.h"

GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/core/half_slope_differentials.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

TEST(Chermain2020Antialiasing, TheBoxIsTheMarginalsMeanOverTheBox) {
    // The box reads the running integral of the piecewise-linear marginal,
    // so it is exact up to float rounding; a 4096-point midpoint rule of the
    // point values has an error far below 1e-3 of the marginal's peak (its
    // kinks cost O(step² / 4096²)), the bound.
    const Dictionary& d = default_dictionary();
    const float step = d.slope_max / float(d.params.table_size);
    Pcg32 rng(11, 12);
    for (int k = 0; k < 200; ++k) {
        const int dist = static_cast<int>(rng.next_uint(d.params.n_dists));
        const int level = static_cast<int>(rng.next_uint(d.params.n_levels));
        const float x = (2.0f * rng.next_float() - 1.0f) * 1.1f * d.slope_max;
        const float width = step * std::exp2(8.0f * rng.next_float() - 4.0f);
        double sum = 0.0;
        float peak = 0.0f;
        const int n = 4096;
        for (int i = 0; i < n; ++i) {
            const float v =
                chermain2020_marginal_box(dist, level, x + width * ((i + 0.5f) / n - 0.5f), 0.0f);
            sum += v;
            peak = std::max(peak, v);
        }
        for (int b = 0; b < d.params.table_size; ++b) peak = std::max(peak, d.at(dist, level, b));
        EXPECT_NEAR(chermain2020_marginal_box(dist, level, x, width), sum / n, 1e-3f * peak)
            << "dist " << dist << " level " << level << " x " << x << " width " << width;
    }
    // Narrower than a hundredth of a step: the point value itself.
    EXPECT_EQ(chermain2020_marginal_box(3, 2, 0.1f, 1e-3f * step),
              chermain2020_marginal_box(3, 2, 0.1f, 0.0f));
}

// The slope −(h_t, h_b)/h_n of normalize(wo + wi) in the frame turned to the
// normal n + e dn (Gram-Schmidt of the tangent), wo moved by e dwo; world =
// the unperturbed local frame.
glm::dvec2 swept_slope(glm::dvec3 wo, glm::dvec3 wi, glm::dvec3 dwo, glm::dvec2 dn, double e) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(e * dn.x, e * dn.y, 1.0));
    const glm::dvec3 t = glm::normalize(glm::dvec3(1, 0, 0) - n.x * n);
    const glm::dvec3 b = glm::cross(n, t);
    const glm::dvec3 h = glm::normalize(glm::normalize(wo + e * dwo) + wi);
    return -glm::dvec2(glm::dot(h, t), glm::dot(h, b)) / glm::dot(h, n);
}

glm::vec3 random_direction(Pcg32& rng, float max_xy) {
    return glm::normalize(glm::vec3(max_xy * (2.0f * rng.next_float() - 1.0f),
                                    max_xy * (2.0f * rng.next_float() - 1.0f), 1.0f));
}

TEST(Chermain2020Antialiasing, HalfSlopeDifferentialsAreTheSlopesDerivatives) {
    // Central differences of the swept slope in double (error O(e²) ~ 1e-6
    // relative) against the float first-order formula: 1e-3 relative to the
    // derivative's scale is far above float rounding and fails on any wrong
    // sign or missing term.
    Pcg32 rng(21, 22);
    for (int k = 0; k < 500; ++k) {
        const glm::vec3 wo = random_direction(rng, 1.5f), wi = random_direction(rng, 1.5f);
        const glm::vec3 dwo(2.0f * rng.next_float() - 1.0f, 2.0f * rng.next_float() - 1.0f,
                            2.0f * rng.next_float() - 1.0f);
        const glm::vec2 dn(2.0f * rng.next_float() - 1.0f, 2.0f * rng.next_float() - 1.0f);
        shader::ViewDifferentials v;
        v.wo = wo;
        v.wo_dx = dwo - wo * glm::dot(wo, dwo);  // a unit vector's change is ⊥ to it
        v.wo_dy = glm::vec3(0.0f);
        v.n_dx = dn;
        v.n_dy = glm::vec2(0.0f);
        const glm::vec3 h = glm::normalize(wo + wi);
        const glm::vec4 got = shader::half_slope_differentials(h, v);
        const double e = 1e-4;
        const glm::dvec2 want =
            (swept_slope(wo, wi, v.wo_dx, dn, e) - swept_slope(wo, wi, v.wo_dx, dn, -e)) /
            (2.0 * e);
        const double scale = 1.0 + glm::length(want);
        EXPECT_NEAR(got.x, want.x, 1e-3 * scale) << k;
        EXPECT_NEAR(got.y, want.y, 1e-3 * scale) << k;
        EXPECT_EQ(got.z, 0.0f);
        EXPECT_EQ(got.w, 0.0f);
    }
}

TEST(Chermain2020Antialiasing, FilteredGlintsApproachThePixelsMeanOverTheSweep) {
    // Sparse, sharp glints (α 0.1: a facet's lobe is 0.004 wide in slope)
    // under a half vector sweeping ~0.02 per pixel: the unfiltered D_P
    // samples the sweep at the pixel centre, a pixel integrates it. The
    // reference is the mean of the unfiltered D_P over a 24 × 24 grid of the
    // pixel's sub-positions (same footprint, so the same cells). The filter
    // (a box per cell axis of the sweep's width) must land closer to it
    // than the centre sample does: RMS error below 0.6 of the unfiltered
    // one's (measured 0.45 with kernel 1; kernels 0.5, 1.25, 2 give 0.84,
    // 0.42, 1.7: a box much wider than the sweep blurs past the pixel's own
    // glints). All three agree in the mean within 5 % (measured 0.6 % and
    // 1.1 %: the box keeps each marginal's integral).
    GlintDesc desc;
    desc.model_id = GlintModelId::Chermain2020;
    desc.ndf = NdfType::Beckmann;
    desc.alpha_x = desc.alpha_y = 0.1f;
    desc.log_density = 9.0f;
    Chermain2020Params params;
    params.antialiasing = true;
    desc.params = params;
    GlintDesc plain = desc;
    std::get<Chermain2020Params>(plain.params).antialiasing = false;
    Pcg32 rng(31, 32);
    double sum_f = 0, sum_u = 0, sum_s = 0, err_f = 0, err_u = 0;
    int n = 0;
    for (int k = 0; k < 400; ++k) {
        const glm::vec3 wo = random_direction(rng, 0.6f);
        const glm::vec3 wi =
            glm::normalize(glm::vec3(-wo.x, -wo.y, wo.z) + 0.05f * random_direction(rng, 1.0f));
        shader::ViewDifferentials v;
        v.wo = wo;
        const glm::vec3 dx = 0.012f * random_direction(rng, 1.0f);
        const glm::vec3 dy = 0.012f * random_direction(rng, 1.0f);
        v.wo_dx = dx - wo * glm::dot(wo, dx);
        v.wo_dy = dy - wo * glm::dot(wo, dy);
        v.n_dx = glm::vec2(0.004f * (2.0f * rng.next_float() - 1.0f), 0.0f);
        v.n_dy = glm::vec2(0.0f, 0.004f * (2.0f * rng.next_float() - 1.0f));
        const Footprint fp{glm::vec2(rng.next_float(), rng.next_float()) * 4.0f,
                           glm::vec2(2e-3f, 0.0f), glm::vec2(0.0f, 2e-3f)};
        const glm::vec3 h = glm::normalize(wo + wi);
        const float f = chermain2020_footprint_ndf(h, fp, desc, &v);
        const float u = chermain2020_footprint_ndf(h, fp, plain, &v);
        double s = 0.0;
        const int m = 24;
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                const double a = (i + 0.5) / m - 0.5, b = (j + 0.5) / m - 0.5;
                // The sub-position's directions in its own turned frame.
                const glm::dvec3 dwo = a * glm::dvec3(v.wo_dx) + b * glm::dvec3(v.wo_dy);
                const glm::dvec2 dn = a * glm::dvec2(v.n_dx) + b * glm::dvec2(v.n_dy);
                const glm::dvec3 nn = glm::normalize(glm::dvec3(dn.x, dn.y, 1.0));
                const glm::dvec3 t = glm::normalize(glm::dvec3(1, 0, 0) - nn.x * nn);
                const glm::dvec3 bb = glm::cross(nn, t);
                const glm::dvec3 hw =
                    glm::normalize(glm::normalize(glm::dvec3(wo) + dwo) + glm::dvec3(wi));
                const glm::vec3 hs(glm::dot(hw, t), glm::dot(hw, bb), glm::dot(hw, nn));
                s += chermain2020_footprint_ndf(hs, fp, plain, nullptr);
            }
        s /= m * m;
        sum_f += f;
        sum_u += u;
        sum_s += s;
        err_f += (f - s) * (f - s);
        err_u += (u - s) * (u - s);
        ++n;
    }
    ASSERT_GT(sum_s, 0.0);
    EXPECT_NEAR(sum_f / sum_s, 1.0, 0.05);
    EXPECT_NEAR(sum_u / sum_s, 1.0, 0.05);
    EXPECT_LT(std::sqrt(err_f / n), 0.6 * std::sqrt(err_u / n))
        << "rms filtered " << std::sqrt(err_f / n) << " unfiltered " << std::sqrt(err_u / n)
        << " mean " << sum_s / n;
}

}  // namespace
}  // namespace glintlab
