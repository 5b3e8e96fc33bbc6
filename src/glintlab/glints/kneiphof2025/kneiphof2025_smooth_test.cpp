// kneiphof2025's two improvements over 003 as published (docs/MODELS.md
// "Decisions and deviations"): the smooth term from the reflection lobe
// (kneiphof2025_lobe_radiance) and the exact conditional law with integer
// trials (binomial_dual_gated_conditional, kneiphof2025_weighted_multinomial).
// Fixed seeds; tolerances argued per test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "glintlab/core/glsl.h"
#include "glintlab/core/image.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"
#include "glintlab/glints/registry.h"
#include "glintlab/microfacet/microfacet.h"
#include "glintlab/scene/environment.h"
#include "glintlab/scene/scene.h"

// Last: it compiles shader code (and its structs) into this file's own namespace.
#include "glintlab/glints/kneiphof2025/kneiphof2025_without_maps_test_util.h"

namespace glintlab {
namespace {

const char* const kForest = "/usr/share/blender/datafiles/studiolights/world/forest.exr";

GlintDesc ggx_desc(float alpha, Kneiphof2025Params::Smooth smooth) {
    GlintDesc d;
    d.model_id = GlintModelId::Kneiphof2025;
    d.ndf = NdfType::GGX;
    d.alpha_x = d.alpha_y = alpha;
    Kneiphof2025Params p;
    p.smooth = smooth;
    d.params = p;
    return d;
}

double binomial_pmf(int n, int k, double p) {
    return std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) +
                    k * std::log(p) + (n - k) * std::log1p(-p));
}

// The conditional law is b(N, p) exactly for integer N where N min(p, 1 - p)
// <= 16 (gates + interior case by inversion): every bin of a 4e5-draw
// histogram within 5 standard errors sqrt(P (1 - P) / M) (+1e-4 for the
// stable power's ~0.1 % relative error on the gates) of the binomial pmf,
// for small, middle and mirrored p. Above the threshold the Gaussian with
// the interior moments leaves < 0.1 % on the mean (N = 300, p = 0.3: the
// standard error of the mean is 0.04 %; limit 0.3 %). Algorithm 1 as
// published stays biased at N p = 1 (+21 %).
TEST(Kneiphof2025Law, ConditionalLawIsTheBinomial) {
    struct Case {
        int n;
        float p;
    };
    const int M = 400000;
    for (const Case c : {Case{2, 0.3f}, Case{5, 0.1f}, Case{10, 0.1f}, Case{40, 0.05f},
                         Case{12, 0.5f}, Case{20, 0.97f}}) {
        Pcg32 rng(7u, static_cast<uint64_t>(c.n));
        std::vector<double> hist(static_cast<size_t>(c.n) + 1, 0.0);
        for (int i = 0; i < M; ++i) {
            const float a = rng.next_float(), b = rng.next_float();
            const glm::vec2 r =
                shader::binomial_dual_gated_conditional(float(c.n), c.p, a, b, true);
            ASSERT_FLOAT_EQ(r.x + r.y, float(c.n));
            hist[static_cast<size_t>(r.x)] += 1.0;
        }
        for (int k = 0; k <= c.n; ++k) {
            const double P = binomial_pmf(c.n, k, c.p);
            const double se = std::sqrt(P * (1.0 - P) / M);
            EXPECT_NEAR(hist[size_t(k)] / M, P, 5.0 * se + 1e-4)
                << "N " << c.n << " p " << c.p << " k " << k;
        }
    }
    Pcg32 rng(8u, 1u);
    double big = 0.0, alg1 = 0.0;
    for (int i = 0; i < M; ++i) {
        const float a = rng.next_float(), b = rng.next_float();
        big += shader::binomial_dual_gated_conditional(300.0f, 0.3f, a, b, true).x;
        alg1 += shader::binomial_dual_gated(10.0f, 0.1f, a, b, true).x;
    }
    EXPECT_NEAR(big / M / 90.0, 1.0, 3e-3);
    EXPECT_GT(alg1 / M / 1.0, 1.1);
}

// The multinomial's mean is exact with a rare bright level (a sun: p = 1e-3,
// L = 3.2e4) and real-valued trials: E[sum_k L_k M_k] = N sum_k L_k p_k. Before
// the fixes (real N, q near 1 drawn directly) the fractional part of N flowed
// into the sun's bin: +20-50 % on its count. 10^6 draws: the relative
// standard error (from the draws' spread) is <= 1 %; limit 5 sigma. Algorithm
// 1 as published is reported against the same expectation (not asserted).
TEST(Kneiphof2025Law, MultinomialMeanIsExactWithARareBrightLevel) {
    const glm::vec4 p_a(0.5f, 0.3f, 0.199f, 1e-3f), L_a(0.0f, 1.0f, 3.0f, 3.2e4f);
    const glm::vec4 zero(0.0f);
    for (const float N : {3.4f, 16.5f, 120.7f}) {
        const double expected = N * glm::dot(p_a, L_a);
        const int M = 1000000;
        Pcg32 rng(11u, static_cast<uint64_t>(N * 10.0f));
        double s = 0.0, s2 = 0.0;
        for (int i = 0; i < M; ++i) {
            uint32_t vs = rng.next_uint();
            const double v =
                shader::kneiphof2025_weighted_multinomial(N, 4, p_a, zero, L_a, zero, true, vs);
            s += v;
            s2 += v * v;
        }
        const double mean = s / M, se = std::sqrt(std::max(s2 / M - mean * mean, 0.0) / M);
        EXPECT_NEAR(mean, expected, 5.0 * se)
            << "N " << N << " relative error " << mean / expected - 1.0 << " se " << se / expected;
    }
}

// Exact smooth radiance int rho~ L dwi (F = 1) at a shading point: multiple
// importance sampling (balance heuristic) of visible normals and of the
// environment, n x n stratified samples each.
double exact_smooth_luminance(const EnvironmentMap& env, glm::vec3 n, glm::vec3 t, glm::vec3 b,
                              glm::vec3 wo, float alpha, Pcg32& rng, int strata) {
    const float g1 = shader::G1_Smith(shader::NDF_GGX, wo, alpha, alpha);
    auto f_pdf = [&](glm::vec3 wi, float* pdf) {
        const glm::vec3 h = glm::normalize(wi + wo);
        const float d = shader::D_Microfacet(shader::NDF_GGX, h, alpha, alpha);
        *pdf = g1 * d / (4.0f * wo.z);
        return shader::G2_SmithCorrelated(shader::NDF_GGX, wo, wi, alpha, alpha) * d /
               (4.0f * wo.z);
    };
    double acc = 0.0;
    for (int i = 0; i < strata; ++i)
        for (int j = 0; j < strata; ++j) {
            const glm::vec2 u((i + rng.next_float()) / strata, (j + rng.next_float()) / strata);
            const glm::vec3 h = shader::sample_vndf_ggx(wo, alpha, alpha, u);
            const float oh = glm::dot(wo, h);
            if (oh > 0.0f) {
                const glm::vec3 wi = 2.0f * oh * h - wo;
                if (wi.z > 0.0f) {
                    float pb = 0.0f;
                    const float f = f_pdf(wi, &pb);
                    const glm::vec3 w = wi.x * t + wi.y * b + wi.z * n;
                    acc += f * luminance(env.eval(w)) / (pb + env.pdf(w));
                }
            }
            glm::vec3 w;
            float pe = 0.0f;
            const glm::vec3 le = env.sample(
                glm::vec2((j + rng.next_float()) / strata, (i + rng.next_float()) / strata), &w,
                &pe);
            const glm::vec3 wi(glm::dot(w, t), glm::dot(w, b), glm::dot(w, n));
            if (pe > 0.0f && wi.z > 0.0f) {
                float pb = 0.0f;
                const float f = f_pdf(wi, &pb);
                acc += f * luminance(le) / (pb + pe);
            }
        }
    return acc / (strata * strata);
}

// The lobe estimate against the exact integral on the 003 Fig. 6 sphere
// (orthographic, 48 x 48, forest.exr) at sqrt(alpha) = 0.5 and 0.7: the image
// mean and the mean of the outer ring (n.z < 0.45, oblique views whose lobe
// the horizon clips) where the split sum is worst. The exact means' Monte
// Carlo error is < 0.3 % (64 + 64 MIS samples per pixel, > 400 pixels per
// ring); both estimates are deterministic. Measured (lobe / split sum):
// image mean +2.3 % / +4.9 % and +3.0 % / +7.4 %; ring +2.9 % / +11 % and
// +2.5 % / +14 %. The lobe's residual is its 32-sample quadrature reading
// maps blurred by the GGX levels (kneiphof2025.glsl). Limits: the lobe within
// 4 %; the split sum's ring error above 10 % at sqrt(alpha) = 0.7 (what the
// lobe estimate fixes) and the lobe's ring error below half of it. A constant
// environment is exact (the ratio estimator keeps E_rho): 1e-5.
TEST(Kneiphof2025Smooth, LobeEstimateMatchesTheExactIntegral) {
    ASSERT_TRUE(std::filesystem::exists(kForest))
        << kForest << " is missing: install Debian's blender-data (scripts/install-deps.sh)";
    const auto env = std::make_shared<const EnvironmentMap>(read_image(kForest), 1.0f, 0.0f);
    const auto pre = kneiphof2025_environment_for(env, 8, 1e-2f);
    const auto white =
        std::make_shared<const EnvironmentMap>(EnvironmentMap::constant(glm::vec3(1.0f)));
    const auto pre_white = kneiphof2025_environment_for(white, 8, 1e-2f);
    const int res = 48;
    for (const float sa : {0.5f, 0.7f}) {
        const float alpha = sa * sa;
        const GlintDesc lobe = ggx_desc(alpha, Kneiphof2025Params::Smooth::Lobe);
        const GlintDesc split = ggx_desc(alpha, Kneiphof2025Params::Smooth::SplitSum);
        Pcg32 rng(3u, 9u);
        double exact[2] = {}, l_sum[2] = {}, s_sum[2] = {};
        for (int y = 0; y < res; ++y)
            for (int x = 0; x < res; ++x) {
                const float px = -1.0f + (x + 0.5f) * 2.0f / res;
                const float py = 1.0f - (y + 0.5f) * 2.0f / res;
                const float r2 = px * px + py * py;
                if (r2 >= 1.0f) continue;
                const glm::vec3 n(px, py, std::sqrt(1.0f - r2));
                if (n.z < 0.05f) continue;
                const float a = -1.0f / (1.0f + n.z), bb = n.x * n.y * a;
                const glm::vec3 t(1.0f + n.x * n.x * a, bb, -n.x),
                    b(bb, 1.0f + n.y * n.y * a, -n.y);
                const glm::vec3 wo(t.z, b.z, n.z);  // (0, 0, 1) in the local frame
                const glm::vec3 wr = 2.0f * n.z * n - glm::vec3(0.0f, 0.0f, 1.0f);
                const double e = exact_smooth_luminance(*env, n, t, b, wo, alpha, rng, 8);
                const double l = luminance(kneiphof2025_environment_smooth(*pre, n, wr, n.z, lobe));
                const double s =
                    luminance(kneiphof2025_environment_smooth(*pre, n, wr, n.z, split));
                for (int ring = 0; ring < 2; ++ring) {
                    if (ring == 1 && n.z >= 0.45f) continue;
                    exact[ring] += e;
                    l_sum[ring] += l;
                    s_sum[ring] += s;
                }
                const glm::vec3 dfg = Kneiphof2025DfgLut::get().lookup(n.z, sa);
                const float e_rho = dfg.x + dfg.y;
                EXPECT_NEAR(
                    luminance(kneiphof2025_environment_smooth(*pre_white, n, wr, n.z, lobe)), e_rho,
                    1e-5f);
            }
        const double lobe_mean = l_sum[0] / exact[0] - 1.0, lobe_ring = l_sum[1] / exact[1] - 1.0;
        const double split_ring = s_sum[1] / exact[1] - 1.0;
        EXPECT_LT(std::abs(lobe_mean), 0.04) << "sqrt(alpha) " << sa;
        EXPECT_LT(std::abs(lobe_ring), 0.04) << "sqrt(alpha) " << sa;
        EXPECT_LT(std::abs(lobe_ring), 0.5 * std::abs(split_ring)) << "sqrt(alpha) " << sa;
        if (sa == 0.7f) {
            EXPECT_GT(split_ring, 0.1);
        }
        std::printf("sqrt(alpha) %.1f: lobe mean %+.4f ring %+.4f; split mean %+.4f ring %+.4f\n",
                    sa, lobe_mean, lobe_ring, s_sum[0] / exact[0] - 1.0, split_ring);
    }
}

}  // namespace
}  // namespace glintlab

namespace glintlab {
namespace {

// Image-mean luminance of a smooth term and of the exact integral over a
// sphere seen in perspective (the scenes/kneiphof2025_sphere.json camera:
// eye at distance 3.2, 45 deg field of view), whole sphere and rim
// (cos_o < 0.4, where the split sum's n = v = r kernel and the missing
// horizon clipping fail).
struct SphereMeans {
    double exact[2] = {}, smooth[2] = {};
    double rel(int region) const { return smooth[region] / exact[region] - 1.0; }
};
SphereMeans perspective_sphere(const EnvironmentMap& env, const Kneiphof2025Environment& pre,
                               const GlintDesc& desc, int res, int strata) {
    SphereMeans m;
    Pcg32 rng(5u, 21u);
    const glm::vec3 eye(0.0f, 0.0f, 3.2f);
    const float th = std::tan(glm::radians(22.5f));
    const float alpha = desc.alpha_x;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const glm::vec3 d =
                glm::normalize(glm::vec3((2.0f * (x + 0.5f) / res - 1.0f) * th,
                                         (1.0f - 2.0f * (y + 0.5f) / res) * th, -1.0f));
            const float bq = glm::dot(eye, d), disc = bq * bq - (glm::dot(eye, eye) - 1.0f);
            if (disc <= 0.0f) continue;
            const glm::vec3 n = glm::normalize(eye + (-bq - std::sqrt(disc)) * d);
            const float cos_o = -glm::dot(n, d);
            if (cos_o <= 1e-3f) continue;
            glm::vec3 t, b;
            shader::tangent_frame(n, t, b);
            const glm::vec3 wo(-glm::dot(d, t), -glm::dot(d, b), cos_o);
            const glm::vec3 wr = glm::reflect(d, n);
            const double e = exact_smooth_luminance(env, n, t, b, wo, alpha, rng, strata);
            const double s = luminance(kneiphof2025_environment_smooth(pre, n, wr, cos_o, desc));
            for (int region = 0; region < 2; ++region) {
                if (region == 1 && cos_o >= 0.4f) continue;
                m.exact[region] += e;
                m.smooth[region] += s;
            }
        }
    return m;
}

const char* const kWorld = "/usr/share/blender/datafiles/studiolights/world/";

// The default smooth term ("lobe_sun") against the exact integral on three
// blender-data maps: sunrise (half its energy in a sun of 4 texels 8 deg
// above the horizon, reflected at the rim: the split sum's worst case),
// city (a high sun) and courtyard (no sun: the lobe alone), at GGX alpha
// 0.25 and 0.5 (sqrt(alpha) 0.5, 0.71). Measured on the 64 x 64 sphere of
// docs/VALIDATION.md over all 8 maps: |error| <= 4.2 % on the image, <= 3.7 %
// on the rim. Here 48 x 48 (32 x 32 under the sanitizers): both estimates
// are deterministic; the exact means' Monte Carlo error (36 + 36 MIS samples
// per pixel, >= 600 sphere pixels, the sun importance-sampled) is < 0.5 %;
// the coarser pixel sets sample the sun's small rim reflection differently
// (measured worst: 3.8 % image / 3.6 % rim at 48, 5.0 % / 4.3 % at 32).
// Limit 6 %. "as_published" (and its alias "split_sum") must stay 003's
// split sum: its measured sunrise errors, +42-46 % image and +58-77 % rim
// at 48 (+46-57 %, +79-99 % at 32; +45-48 %, +65-83 % at 64), pinned to
// [+35 %, +60 %] image and > +45 % rim.
TEST(Kneiphof2025Smooth, LobeSunDefaultMatchesTheExactIntegralOnSunMaps) {
#if defined(__SANITIZE_ADDRESS__)
    const int res = 32;
#else
    const int res = 48;
#endif
    EXPECT_EQ(Kneiphof2025Params{}.smooth, Kneiphof2025Params::Smooth::LobeSun);
    // The scene key: "as_published" and the old name "split_sum" select the split sum.
    for (const GlintParam& p : glint_model(GlintModelId::Kneiphof2025).params) {
        if (p.key != "smooth") continue;
        for (const char* name : {"as_published", "split_sum"}) {
            GlintModelParams v = Kneiphof2025Params{};
            p.set(v, GlintParamValue(std::string(name)));
            EXPECT_EQ(std::get<Kneiphof2025Params>(v).smooth, Kneiphof2025Params::Smooth::SplitSum);
            EXPECT_EQ(std::get<std::string>(p.get(v)), "as_published");
        }
    }
    for (const char* name : {"sunrise", "city", "courtyard"}) {
        const std::string path = std::string(kWorld) + name + ".exr";
        ASSERT_TRUE(std::filesystem::exists(path))
            << path << " is missing: install Debian's blender-data (scripts/install-deps.sh)";
        const auto env = std::make_shared<const EnvironmentMap>(read_image(path), 1.0f, 0.0f);
        const auto pre = kneiphof2025_environment_for(env, 8, 1e-2f);
        // Sunrise and city have a sun by the rule of Kneiphof2025Sources;
        // courtyard (max luminance 53, no compact source) has none.
        EXPECT_EQ(pre->sources().empty(), std::string(name) == "courtyard") << name;
        for (const float alpha : {0.25f, 0.5f}) {
            const SphereMeans m = perspective_sphere(
                *env, *pre, ggx_desc(alpha, Kneiphof2025Params::Smooth::LobeSun), res, 6);
            EXPECT_LT(std::abs(m.rel(0)), 0.06) << name << " alpha " << alpha;
            EXPECT_LT(std::abs(m.rel(1)), 0.06) << name << " alpha " << alpha << " (rim)";
            std::printf("%-9s alpha %.2f: lobe_sun image %+.4f rim %+.4f\n", name, alpha, m.rel(0),
                        m.rel(1));
            if (std::string(name) == "sunrise") {
                const SphereMeans s = perspective_sphere(
                    *env, *pre, ggx_desc(alpha, Kneiphof2025Params::Smooth::SplitSum), res, 6);
                EXPECT_GT(s.rel(0), 0.35) << "alpha " << alpha;
                EXPECT_LT(s.rel(0), 0.60) << "alpha " << alpha;
                EXPECT_GT(s.rel(1), 0.45) << "alpha " << alpha;
                std::printf("sunrise   alpha %.2f: as_published image %+.4f rim %+.4f\n", alpha,
                            s.rel(0), s.rel(1));
            }
        }
    }
}

}  // namespace
}  // namespace glintlab

namespace glintlab {
namespace {

// Image-mean luminance of a smooth term and of the exact integral over the
// 2 x 2 quad y = 0 seen 25 deg above it (eye (0, 1.268, 2.719), 45 deg field
// of view: the scenes/compare plane's view), res x res pixels.
SphereMeans grazing_plane(const EnvironmentMap& env, const Kneiphof2025Environment& pre,
                          const GlintDesc& desc, int res, int strata) {
    SphereMeans m;
    Pcg32 rng(7u, 13u);
    const glm::vec3 eye(0.0f, 1.268f, 2.719f);
    const glm::vec3 fwd = glm::normalize(-eye);
    const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, fwd);
    const float th = std::tan(glm::radians(22.5f));
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    glm::vec3 t, b;
    shader::tangent_frame(n, t, b);
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const glm::vec3 d = glm::normalize(fwd + (2.0f * (x + 0.5f) / res - 1.0f) * th * right +
                                               (1.0f - 2.0f * (y + 0.5f) / res) * th * up);
            if (!(d.y < 0.0f)) continue;
            const glm::vec3 p = eye + (-eye.y / d.y) * d;
            if (std::abs(p.x) > 1.0f || std::abs(p.z) > 1.0f) continue;
            const float cos_o = -d.y;
            const glm::vec3 wo(-glm::dot(d, t), -glm::dot(d, b), cos_o);
            const glm::vec3 wr = glm::reflect(d, n);
            const double e = exact_smooth_luminance(env, n, t, b, wo, desc.alpha_x, rng, strata);
            const double s = luminance(kneiphof2025_environment_smooth(pre, n, wr, cos_o, desc));
            m.exact[0] += e;
            m.smooth[0] += s;
        }
    return m;
}

// The default smooth term against the exact integral on a plane seen 25 deg
// above it under blender's studio map: several small lamps near the
// horizon (87 % of the map's power above 10x its mean), reflected in the
// lobe's tail at grazing view. The lobe's 32 samples read them through
// blurred levels as if they sat near the lobe's peak; "lobe_sun" takes them
// out as 16 directions. Measured at 32 x 32 (the exact means' Monte Carlo
// error: 0.15 % between 8 x 8 and 24 x 24 strata): lobe_sun +4.3 % (alpha
// 0.09), -1.3 % (0.25); the lobe alone +297 %, +48 %. Limits: lobe_sun
// within 8 %; the lobe alone above +100 % at alpha 0.09 (what the sources fix).
TEST(Kneiphof2025Smooth, LobeSunHoldsOnAGrazingPlaneUnderManyLamps) {
    const std::string path = std::string(kWorld) + "studio.exr";
    ASSERT_TRUE(std::filesystem::exists(path))
        << path << " is missing: install Debian's blender-data (scripts/install-deps.sh)";
    const auto env = std::make_shared<const EnvironmentMap>(read_image(path), 1.0f, 0.0f);
    const auto pre = kneiphof2025_environment_for(env, 8, 1e-2f);
    ASSERT_FALSE(pre->sources().empty());
    for (const float alpha : {0.09f, 0.25f}) {
        const SphereMeans sun =
            grazing_plane(*env, *pre, ggx_desc(alpha, Kneiphof2025Params::Smooth::LobeSun), 32, 8);
        const SphereMeans lobe =
            grazing_plane(*env, *pre, ggx_desc(alpha, Kneiphof2025Params::Smooth::Lobe), 32, 8);
        std::printf("studio plane alpha %.2f: lobe_sun %+.4f lobe %+.4f\n", alpha, sun.rel(0),
                    lobe.rel(0));
        EXPECT_LT(std::abs(sun.rel(0)), 0.08) << "alpha " << alpha;
        if (alpha < 0.1f) {
            EXPECT_GT(lobe.rel(0), 1.0);
        }
    }
}

}  // namespace
}  // namespace glintlab
