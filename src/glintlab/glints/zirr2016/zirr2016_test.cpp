// Tests of the zirr2016 baseline ([ZK16] as restated in 000 §3, Eq. 4, 7, 15).

#include "glintlab/glints/zirr2016/zirr2016.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/glint_reader.h"
#include "glintlab/glints/registry.h"
#include "glintlab/glints/zirr2016/zirr2016_experiments.h"
#include "glintlab/scene/scene.h"

namespace glintlab {
namespace {

Footprint axis_footprint(glm::vec2 uv, float minor, float ratio) {
    Footprint fp;
    fp.uv = uv;
    fp.duvdx = glm::vec2(minor * ratio, 0.0f);
    fp.duvdy = glm::vec2(0.0f, minor);
    return fp;
}

// 000 Eq. 5-6. At ln density 30 a texel (~1e-6 uv^2) holds ~1e7 facets and
// N p >= 4900 for every case (p >= R D(h)/D(n) = 0.025 e^-4 at tan = 2 alpha),
// so one footprint's relative noise is <= 1/sqrt(4900) = 1.4 % and the mean
// of 100 is within 0.15 % (1 sigma); Eq. 15's floor biases by 1/(2 N p) < 1e-4.
// The 2 % limit is > 10 sigma away from noise.
TEST(Zirr2016, ConvergesToSmoothNdfAtHighDensity) {
    for (const Zirr2016ConvergenceCase& c : zirr2016_convergence(30.0f, 100, 7)) {
        EXPECT_LE(c.rel_err, 0.02)
            << "ndf " << c.ndf << " alpha " << c.alpha << " tan " << c.tan_theta;
    }
}

// Eq. 15 floors the Gaussian: E[floor(G)] = N p - 1/2 when its std-dev is
// >~ 0.5, so at N p = 10 the mean count is 0.95 of N p. Isotropic footprint
// exactly at a level (w ~ 0), h = n so p = R. Var(C) = (4/9)(N p (1-p) + 1/12)
// ~ 4.0 (bilinear angular blend with a uniform offset: E[sum w_c^2] = 4/9),
// so the mean of 4000 ratios has sigma 2.0/10/sqrt(4000) = 0.0032: 0.015 is
// ~5 sigma, and an unbiased law (ratio 1) fails by 15 sigma.
TEST(Zirr2016, FlooredGaussianBranchIsBiasedByHalfAFacet) {
    const Zirr2016CountStats s = zirr2016_count_stats(-9.9999, 100.0, 0.1f, 4000, 11);
    EXPECT_NEAR(s.mean_ratio, 0.95, 0.015);
}

// N p <= 5 and N <= 16: the exact Bernoulli sum, mean N p. N = 8, p = 0.25:
// Var(C) = (4/9) 1.5, relative sigma of one footprint 0.41, of the mean of
// 4000: 0.0065; 0.035 is > 5 sigma.
TEST(Zirr2016, BernoulliBranchIsUnbiased) {
    const Zirr2016CountStats s = zirr2016_count_stats(-9.9999, 8.0, 0.25f, 4000, 12);
    EXPECT_NEAR(s.mean_ratio, 1.0, 0.035);
}

// 000 Eq. 7 / Fig. 4b: blending the outputs of the two levels keeps the mean
// but not the binomial variance. With N_bottom = 400, p = 0.1, N_top = 1600:
//   Var(C) = (4/9) [(1-w)^2 (40 * 0.9 + 1/12) + w^2 (160 * 0.9 + 1/12)],
//   E[C]   = (1-w) (40 - 1/2) + w (160 - 1/2),
// Var/E = 0.406 at w = 0 and 0.201 at w = 1/2 (a true binomial of the blended
// area keeps ~0.9 x 4/9 = 0.4). The sample variance of 4000 footprints has
// relative sigma ~ sqrt(2/4000) = 2.2 %: 10 % is > 4 sigma.
TEST(Zirr2016, OutputBlendingHalvesCountVarianceMidLevel) {
    auto theory = [](double w) {
        const double var =
            4.0 / 9.0 * ((1 - w) * (1 - w) * (36.0 + 1.0 / 12) + w * w * (144.0 + 1.0 / 12));
        const double mean = (1 - w) * 39.5 + w * 159.5;
        return var / mean;
    };
    const Zirr2016CountStats at_level = zirr2016_count_stats(-9.9999, 400.0, 0.1f, 4000, 21);
    const Zirr2016CountStats mid = zirr2016_count_stats(-9.5, 400.0, 0.1f, 4000, 22);
    EXPECT_NEAR(at_level.variance_over_mean / theory(0.0001), 1.0, 0.1);
    EXPECT_NEAR(mid.variance_over_mean / theory(0.5), 1.0, 0.1);
    EXPECT_LT(mid.variance_over_mean, 0.6 * at_level.variance_over_mean);
}

TEST(Zirr2016, NoNanOrNegativeOverWholeDomain) {
    const Zirr2016RobustnessResult r = zirr2016_robustness(100000, 3);
    EXPECT_EQ(r.bad, 0);
}

TEST(Zirr2016, DeterministicSeededAndZeroBelowHorizon) {
    Zirr2016Target t;
    t.log_density = 14.0f;  // sparse: a few facets per angular cell
    const Zirr2016Params p;
    const glm::vec3 h = glm::normalize(glm::vec3(0.05f, -0.02f, 1.0f));
    int differ = 0;
    Pcg32 rng(0, 5);
    for (int i = 0; i < 200; ++i) {
        const Footprint fp =
            axis_footprint(glm::vec2(rng.next_float(), rng.next_float()), 1e-3f, 3.0f);
        t.seed = 1;
        const float a = zirr2016_ndf(h, fp, t, p);
        EXPECT_EQ(a, zirr2016_ndf(h, fp, t, p));
        t.seed = 2;
        if (zirr2016_ndf(h, fp, t, p) != a) ++differ;
        EXPECT_EQ(zirr2016_ndf(glm::vec3(0.0f, 0.0f, -1.0f), fp, t, p), 0.0f);
    }
    // N ~ 1e6 e^14 ~ 1.2 per texel: another seed gives another count almost always.
    EXPECT_GT(differ, 150);
}

// 000 §7 / Fig. 11: beyond max_anisotropy the footprint is widened
// isotropically, i.e. a ratio-100 footprint shades like the ratio-16 one with
// the same major axis. Same LOD, same 16 march points up to rounding: equal
// to fp32 precision.
TEST(Zirr2016, AnisotropyBeyondLimitWidensTheFootprint) {
    Zirr2016Target t;
    t.log_density = 20.0f;
    const Zirr2016Params p;  // max_anisotropy 16
    const glm::vec3 h = glm::normalize(glm::vec3(0.03f, 0.01f, 1.0f));
    Pcg32 rng(0, 9);
    for (int i = 0; i < 50; ++i) {
        t.seed = rng.next_uint();
        const glm::vec2 uv(rng.next_float(), rng.next_float());
        const float major = 0.0150f;  // minor 0.0150/16: LOD -10.06, away from a level
        const float clamped = zirr2016_ndf(h, axis_footprint(uv, major / 100.0f, 100.0f), t, p);
        const float widened = zirr2016_ndf(h, axis_footprint(uv, major / 16.0f, 16.0f), t, p);
        EXPECT_NEAR(clamped, widened, 1e-4f * std::abs(widened) + 1e-6f);
    }
}

// JsonObject keeps a reference to its json value: the values are named locals.
TEST(Zirr2016, ReadsParametersWithRangeChecks) {
    GlintDesc desc;
    const nlohmann::json ok_json =
        nlohmann::json::parse(R"({"microfacet_roughness": 0.03, "max_anisotropy": 8})");
    JsonObject ok(ok_json, "/zirr2016", "scene.json");
    read_glint_params(*find_glint_model("zirr2016"), ok, desc);
    const Zirr2016Params& p = std::get<Zirr2016Params>(desc.params);
    EXPECT_FLOAT_EQ(p.microfacet_roughness, 0.03f);
    EXPECT_FLOAT_EQ(p.max_anisotropy, 8.0f);
    EXPECT_FLOAT_EQ(p.screen_space_scale, 1.0f);
    const nlohmann::json bad_json = nlohmann::json::parse(R"({"max_anisotropy": 65})");
    JsonObject bad(bad_json, "/zirr2016", "scene.json");
    EXPECT_THROW(read_glint_params(*find_glint_model("zirr2016"), bad, desc), Error);
    const nlohmann::json zero_r_json = nlohmann::json::parse(R"({"microfacet_roughness": 0})");
    JsonObject zero_r(zero_r_json, "/zirr2016", "scene.json");
    EXPECT_THROW(read_glint_params(*find_glint_model("zirr2016"), zero_r, desc), Error);
    const nlohmann::json unknown_json = nlohmann::json::parse(R"({"roughness": 0.1})");
    JsonObject unknown(unknown_json, "/zirr2016", "scene.json");
    EXPECT_THROW(read_glint_params(*find_glint_model("zirr2016"), unknown, desc), Error);

    const GlintModelInfo* info = find_glint_model("zirr2016");
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->id, GlintModelId::Zirr2016);
    EXPECT_TRUE(info->shades(GlintLightType::Point) && info->shades(GlintLightType::Directional));
    EXPECT_FALSE(info->shades(GlintLightType::Sphere) || info->shades(GlintLightType::Environment));
}

}  // namespace
}  // namespace glintlab
