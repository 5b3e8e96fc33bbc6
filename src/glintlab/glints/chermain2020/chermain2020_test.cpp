#include "glintlab/glints/chermain2020/chermain2020.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/chermain2020/chermain2020_experiments.h"
#include "glintlab/glints/glint_bxdf.h"
#include "glintlab/glints/glint_reader.h"
#include "glintlab/glints/registry.h"
#include "glintlab/microfacet/microfacet.h"
#include "glintlab/scene/scene.h"

namespace glintlab {
namespace {

Footprint footprint_at(glm::vec2 uv, float minor, float aniso, float angle) {
    const glm::vec2 e1(std::cos(angle), std::sin(angle)), e2(-e1.y, e1.x);
    return Footprint{uv, e1 * (minor * aniso), e2 * minor};
}

TEST(Chermain2020, ConvergesToBeckmann) {
    // Mean of D_P over 300 footprints (LOD 4-5, l_dist 14-15). Per footprint
    // the relative spread of D_P is ~4 % / sqrt(cells) (two marginals of
    // 1.6e4-3.3e4 lobes, kernel noise ~2.8 % each), ~1.5 % for the smallest
    // footprints, so the mean is within 0.3 % (3 sigma over 300); the
    // dictionary's own bias (kernel smoothing, 192 marginals) is < 0.5 %.
    // 2 % is the convergence bound, well above both.
    for (const auto& c : chermain2020_convergence(300, 7))
        EXPECT_LE(c.rel_err, 0.02)
            << c.alpha_x << " " << c.alpha_y << " " << c.tan_theta << " " << c.phi << " rho "
            << c.rho << " mean " << c.mean_dp << " target " << c.target;
}

TEST(Chermain2020, WeakWhiteFurnace) {
    // 004 Eq. 17: exactly 1 for every cell, since each cell's SDF is
    // normalised and even (V-cavity furnace, Heitz 2014); the quadrature
    // integrates the piecewise-linear lobes exactly, so what is left is the
    // Gauss-Legendre error on the smooth masking weight, ~1e-4.
    Chermain2020FurnaceSweep s;
    s.alphas = {0.1f, 0.5f};
    s.log_densities = {20.0f, 40.0f};
    s.zetas = {0.0f, 2.0f};
    s.theta_os = {0.0f, 0.7854f, 1.3f};
    s.cells_per_case = 1;
    for (const auto& c : chermain2020_furnace(s, 3))
        EXPECT_LE(c.rel_err, 0.003)
            << "alpha " << c.alpha << " log rho " << c.log_density << " zeta " << c.zeta
            << " theta_o " << c.theta_o << " l_dist " << c.dist_level << " value " << c.value;
}

TEST(Chermain2020, Reciprocal) {
    // Only F(wo.h) and F(wi.h) are computed from different fp32 dot products
    // of a rounded half vector: <= ~3e-5 relative for wo.h >= 0.05 (bound in
    // validate_chermain2020.cpp).
    EXPECT_LE(chermain2020_reciprocity(3000, 5), 1e-4);
}

TEST(Chermain2020, NoNanOrNegative) {
    EXPECT_EQ(chermain2020_robustness(20000, 11), 0);
}

TEST(Chermain2020, CoherentIndexingKeepsParentChoices) {
    // Eq. 8 / Fig. 7: the cell (x, y) of level l+1 is seeded like its child
    // (2x, 2y) of level l: same marginals and rotation, one dictionary level
    // more (the facet count quadruples, Alg. 3 line 5).
    Chermain2020Target t;
    t.log_density = 20.0f;  // l_dist well inside [0, 15] at levels 3-9
    Chermain2020Params p;
    int differing_siblings = 0;
    Pcg32 rng(1, 2);
    for (int k = 0; k < 200; ++k) {
        const glm::ivec2 parent(static_cast<int>(rng.next_uint(4096)) - 2048,
                                static_cast<int>(rng.next_uint(4096)) - 2048);
        const int level = 3 + static_cast<int>(rng.next_uint(6));
        const auto up = chermain2020_cell(parent, level + 1, t, p);
        const auto child = chermain2020_cell(parent * 2, level, t, p);
        const auto sibling = chermain2020_cell(parent * 2 + glm::ivec2(1, 0), level, t, p);
        EXPECT_EQ(up.dist_x, child.dist_x);
        EXPECT_EQ(up.dist_y, child.dist_y);
        EXPECT_EQ(up.theta, child.theta);
        EXPECT_EQ(up.dist_level, child.dist_level + 1);
        differing_siblings += sibling.dist_x != child.dist_x || sibling.dist_y != child.dist_y;
    }
    // Independent siblings coincide with probability 1/192^2 per cell.
    EXPECT_GE(differing_siblings, 198);
}

// Algorithm 2 as written: every cell of the ellipse's bounding box, the
// r^2 < 1 test, the truncated Gaussian weight, the eager cell evaluation;
// the cell under the centre where no cell centre is inside. The
// expressions are those of chermain2020.glsl, so the sums agree bit for bit
// with its walk (which visits only the rows' ranges, lazily).
float level_sdf_by_box_scan(glm::vec2 slope, glm::vec2 uv, glm::vec3 ellipse, int level,
                            const Chermain2020Target& t, const Chermain2020Params& p, int n_levels,
                            bool& fell_back) {
    const float scale = std::exp2(static_cast<float>(n_levels - 1 - level));
    const glm::vec2 centre = uv * scale;
    const float major = ellipse.x * scale, minor = ellipse.y * scale;
    const float ca = std::cos(ellipse.z), sa = std::sin(ellipse.z);
    const float ex = std::min(std::sqrt(major * major * ca * ca + minor * minor * sa * sa), 32.0f);
    const float ey = std::min(std::sqrt(major * major * sa * sa + minor * minor * ca * ca), 32.0f);
    const int x0 = static_cast<int>(std::floor(centre.x - ex));
    const int x1 = static_cast<int>(std::floor(centre.x + ex));
    const int y0 = static_cast<int>(std::floor(centre.y - ey));
    const int y1 = static_cast<int>(std::floor(centre.y + ey));
    float sum_p = 0.0f, sum_w = 0.0f;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 q =
                glm::vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f) - centre;
            const float a = (q.x * ca + q.y * sa) / major;
            const float b = (-q.x * sa + q.y * ca) / minor;
            const float r2 = a * a + b * b;
            if (r2 >= 1.0f) continue;
            const float w = std::exp(-2.0f * r2) - 0.13533528f;
            const float p22 =
                chermain2020_cell_p22(chermain2020_cell({x, y}, level, t, p), slope, t);
            if (p22 > 0.0f) sum_p += w * p22;
            sum_w += w;
        }
    fell_back = !(sum_w > 0.0f);
    if (!fell_back) return sum_p / sum_w;
    const glm::ivec2 under(static_cast<int>(std::floor(centre.x)),
                           static_cast<int>(std::floor(centre.y)));
    return chermain2020_cell_p22(chermain2020_cell(under, level, t, p), slope, t);
}

TEST(Chermain2020, WalkMatchesTheBoundingBoxScan) {
    // The GPU-cost walk of Algorithm 2 (row ranges from the ellipse's roots,
    // one flat loop, the fallback cell as its last step; docs/MODELS.md,
    // chermain2020) must visit the same cells in the same order as the scan of
    // the whole bounding box: same sums, bit for bit, for ellipses from
    // below a cell (the fallback) to the 64-cell cap, every orientation and
    // anisotropies up to 64 (beyond the clamp, which the walk does not rely
    // on), with density randomisation and the relative-area test on.
    Chermain2020Target t;
    t.log_density = 20.0f;
    t.alpha_x = 0.4f;
    t.alpha_y = 0.3f;
    t.seed = 77;
    Chermain2020Params p;
    p.relative_area = 0.8f;
    p.density_randomization = 2.0f;
    const int n_levels = 16;  // the default dictionary's
    Pcg32 rng(5, 9);
    int fell_back = 0, non_zero = 0;
    for (int k = 0; k < 3000; ++k) {
        const int level = static_cast<int>(rng.next_uint(10));
        const float cell = std::exp2(static_cast<float>(level - (n_levels - 1)));  // uv size
        const float major_cells = std::exp2(-3.0f + 9.0f * rng.next_float());      // 1/8 .. 64
        const float aniso = std::exp2(6.0f * rng.next_float());                    // 1 .. 64
        const glm::vec3 ellipse(major_cells * cell, major_cells / aniso * cell,
                                (rng.next_float() - 0.5f) * 3.14159265f);
        const glm::vec2 uv(4.0f * rng.next_float(), 4.0f * rng.next_float());
        // Slopes within the target's lobe, where most cells are non-zero.
        const glm::vec2 slope(0.8f * (rng.next_float() - 0.5f), 0.6f * (rng.next_float() - 0.5f));
        bool fb = false;
        const float expected = level_sdf_by_box_scan(slope, uv, ellipse, level, t, p, n_levels, fb);
        const glm::vec3 walked = chermain2020_level_sdf(slope, uv, ellipse, level, t, p);
        ASSERT_EQ(walked.x, expected)
            << "k " << k << " level " << level << " major " << major_cells << " aniso " << aniso;
        EXPECT_EQ(walked.y, expected);
        fell_back += fb;
        non_zero += expected > 0.0f;
    }
    // The cases the walk must get right occur: footprints below a cell
    // (major < 1/2 cell: ~10 % of draws) and sums with non-zero cells.
    EXPECT_GE(fell_back, 100);
    EXPECT_GE(non_zero, 1000);
}

TEST(Chermain2020, RelativeAreaScalesTheMean) {
    // E[D_P] = beta D (Alg. 3 line 4 keeps a cell with probability beta).
    // ~20 cells per footprint: relative std-dev of one footprint's D_P is
    // ~sqrt((1 - beta) / (beta * 20)) = 22 %, 1.3 % over 300; 3 sigma = 4 %.
    Chermain2020Target t;
    t.alpha_x = t.alpha_y = 0.3f;
    t.log_density = 40.0f;  // analytic cells: only beta varies
    Chermain2020Params p;
    p.relative_area = 0.5f;
    const glm::vec3 h = glm::normalize(glm::vec3(0.1f, -0.05f, 1.0f));
    Pcg32 rng(3, 4);
    double sum = 0.0;
    const int n = 300;
    for (int k = 0; k < n; ++k) {
        const Footprint fp =
            footprint_at(glm::vec2(rng.next_float(), rng.next_float()) * 8.0f,
                         std::exp2(5.0f - 15.0f), 4.0f, 6.2832f * rng.next_float());
        sum += chermain2020_ndf(h, fp, t, p);
    }
    EXPECT_NEAR(sum / n / chermain2020_target_ndf(h, t), 0.5, 0.04 * 0.5);
}

TEST(Chermain2020, ContinuousAcrossLodBoundary) {
    // Alg. 1 line 8: at an integer LOD the lerp weight of the finer level
    // vanishes from above and that of the coarser one is 1 from below, and
    // the cell weights move continuously with the footprint: a 1e-4 LOD step
    // changes D_P by ~1e-4 of its scale. 1e-2 fails on any jump.
    Chermain2020Target t;
    t.alpha_x = t.alpha_y = 0.4f;
    t.log_density = 30.0f;
    Chermain2020Params p;
    Pcg32 rng(5, 6);
    int compared = 0;
    for (int k = 0; k < 100; ++k) {
        const glm::vec2 uv(rng.next_float(), rng.next_float());
        const float angle = 6.2832f * rng.next_float();
        const glm::vec3 h = glm::normalize(
            glm::vec3(0.4f * (rng.next_float() - 0.5f), 0.4f * (rng.next_float() - 0.5f), 1.0f));
        const float lod = 3.0f + static_cast<float>(rng.next_uint(5));
        const float a = chermain2020_ndf(
            h, footprint_at(uv, std::exp2(lod - 1e-4f - 15.0f), 3.0f, angle), t, p);
        const float b = chermain2020_ndf(
            h, footprint_at(uv, std::exp2(lod + 1e-4f - 15.0f), 3.0f, angle), t, p);
        const float scale = std::max(a, b);
        if (scale <= 0.0f) continue;
        ++compared;
        EXPECT_LE(std::abs(a - b) / scale, 1e-2f) << "lod " << lod << ": " << a << " vs " << b;
    }
    EXPECT_GE(compared, 50);
}

TEST(Chermain2020, ReadsParametersAndRejectsGgx) {
    // JsonObject keeps a reference to its json value: the values are named locals.
    GlintDesc desc;
    desc.ndf = NdfType::Beckmann;
    const nlohmann::json ok_json = {{"relative_area", 0.25}, {"max_anisotropy", 4}};
    JsonObject ok(ok_json, "/materials/0/chermain2020", "scene.json");
    read_glint_params(*find_glint_model("chermain2020"), ok, desc);
    const auto& p = std::get<Chermain2020Params>(desc.params);
    EXPECT_EQ(p.relative_area, 0.25f);
    EXPECT_EQ(p.max_anisotropy, 4.0f);
    EXPECT_EQ(p.density_randomization, 0.0f);
    const nlohmann::json bad_json = {{"max_anisotropy", 0.5}};
    JsonObject bad(bad_json, "/materials/0/chermain2020", "scene.json");
    EXPECT_THROW(read_glint_params(*find_glint_model("chermain2020"), bad, desc), Error);
    desc.ndf = NdfType::GGX;
    const nlohmann::json empty = nlohmann::json::object();
    JsonObject ggx(empty, "/materials/0/chermain2020", "scene.json");
    try {
        read_glint_params(*find_glint_model("chermain2020"), ggx, desc);
        ADD_FAILURE() << "ggx accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("beckmann"), std::string::npos) << e.what();
    }
}

// Masking: by default the height-correlated Smith G2 of the target, so the
// smooth limit is the smooth model's lobe (the ground truth's expectation)
// at every angle; "v_cavity" is 004's G2 (Eq. 14-16), equal near the normal
// and 27 % brighter at a grazing 82.5° view. The ratio of the two images is
// G2_VCavity / G2_SmithCorrelated exactly, since D_P and F are shared.
TEST(Chermain2020, MaskingIsSmithByDefaultAndVCavityAsPublished) {
    GlintDesc desc;
    desc.model_id = GlintModelId::Chermain2020;
    desc.ndf = NdfType::Beckmann;
    desc.alpha_x = desc.alpha_y = 0.3f;
    const nlohmann::json v_json = {{"masking", "v_cavity"}};
    JsonObject v_block(v_json, "/materials/0/chermain2020", "scene.json");
    GlintDesc v_cavity = desc;
    read_glint_params(*find_glint_model("chermain2020"), v_block, v_cavity);
    ASSERT_TRUE(std::get<Chermain2020Params>(v_cavity.params).v_cavity_masking);
    desc.params = Chermain2020Params{};
    GlintDesc smooth = desc;
    smooth.model_id = GlintModelId::Smooth;
    const nlohmann::json none = nlohmann::json::object();
    JsonObject smooth_block(none, "/materials/0/smooth", "scene.json");
    read_glint_params(*find_glint_model("smooth"), smooth_block, smooth);
    auto f = [](const GlintDesc& d, glm::vec3 wo, glm::vec3 wi) {
        GlintBxdf b;
        b.desc = &d;
        return b.f(wo, wi).x;  // no footprint: the model's smooth limit
    };
    auto dir = [](float theta_deg, float phi) {
        const float t = theta_deg * std::numbers::pi_v<float> / 180.0f;
        return glm::vec3(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t));
    };
    const float quarter = 0.5f * std::numbers::pi_v<float>;
    for (const auto& [theta_o, theta_i] : {std::pair{30.0f, 30.0f},
                                           {60.0f, 60.0f},
                                           {75.0f, 71.0f},
                                           {82.5f, 70.7f},
                                           {88.0f, 70.7f}}) {
        const glm::vec3 wo = dir(theta_o, quarter), wi = dir(theta_i, -quarter);
        const glm::vec3 h = glm::normalize(wo + wi);
        const float s = f(smooth, wo, wi);
        ASSERT_GT(s, 0.0f);
        EXPECT_NEAR(f(desc, wo, wi) / s, 1.0f, 1e-5f) << theta_o;
        const float g_ratio = shader::G2_VCavity(wo, wi, h) /
                              shader::G2_SmithCorrelated(shader::NDF_BECKMANN, wo, wi, 0.3f, 0.3f);
        EXPECT_NEAR(f(v_cavity, wo, wi) / s, g_ratio, 1e-5f * g_ratio) << theta_o;
        if (theta_o == 82.5f) {
            EXPECT_NEAR(g_ratio, 1.275f, 0.01f);
        }
        if (theta_o <= 60.0f) {
            EXPECT_NEAR(g_ratio, 1.0f, 0.01f);
        }
    }
}

TEST(Chermain2020, ColouredGlintsSplitTheScalarSdf) {
    // Alg. 3 lines 11-12, 19: each cell multiplies its SDF by one table colour.
    // With the table {red, blue} every cell's contribution goes to exactly one
    // of R and B, so R + B equals the scalar D_P (up to fp32 rounding of the
    // sums) and G is 0; a one-colour table scales D_P by that colour.
    Chermain2020Target t;
    t.alpha_x = t.alpha_y = 0.4f;
    t.log_density = 22.0f;
    Chermain2020Params two;
    two.colour_count = 2;
    two.colour_table[0] = glm::vec3(1, 0, 0);
    two.colour_table[1] = glm::vec3(0, 0, 1);
    Chermain2020Params one;
    one.colour_count = 1;
    one.colour_table[0] = glm::vec3(0.25f, 0.5f, 1.0f);
    Pcg32 rng(5, 11);
    double red = 0.0, total = 0.0;
    for (int i = 0; i < 400; ++i) {
        const glm::vec2 uv(rng.next_float(), rng.next_float());
        const Footprint fp =
            footprint_at(uv, 2e-4f, 1.0f + 3.0f * rng.next_float(), 6.28f * rng.next_float());
        const glm::vec3 h = glm::normalize(
            glm::vec3(0.4f * (rng.next_float() - 0.5f), 0.4f * (rng.next_float() - 0.5f), 1.0f));
        const float d = chermain2020_ndf(h, fp, t, Chermain2020Params{});
        const glm::vec3 rb = chermain2020_ndf_rgb(h, fp, t, two);
        EXPECT_EQ(rb.y, 0.0f);
        EXPECT_NEAR(rb.x + rb.z, d, 1e-5f * d + 1e-30f);
        const glm::vec3 c = chermain2020_ndf_rgb(h, fp, t, one);
        EXPECT_NEAR(c.x, 0.25f * d, 1e-6f * d + 1e-30f);
        EXPECT_NEAR(c.z, d, 1e-6f * d + 1e-30f);
        red += rb.x;
        total += d;
    }
    // Colours are drawn uniformly per cell: the red share of the summed D_P is
    // 1/2 up to the spread of the per-cell weights; with ~400 footprints of
    // tens of cells each the share's std-dev is < 2 %, so 0.5 +- 0.08 is > 4 sigma.
    ASSERT_GT(total, 0.0);
    EXPECT_NEAR(red / total, 0.5, 0.08);
}

TEST(Chermain2020, ReadsColourTable) {
    GlintDesc desc;
    desc.ndf = NdfType::Beckmann;
    const nlohmann::json ok_json = {{"colours", {{1, 0.5, 0}, {0, 0, 1}}}};
    JsonObject ok(ok_json, "/materials/0/chermain2020", "scene.json");
    read_glint_params(*find_glint_model("chermain2020"), ok, desc);
    const auto& p = std::get<Chermain2020Params>(desc.params);
    EXPECT_EQ(p.colour_count, 2);
    EXPECT_EQ(p.colour_table[0], glm::vec3(1, 0.5f, 0));
    for (const nlohmann::json& bad_json :
         {nlohmann::json{{"colours", nlohmann::json::array()}},
          nlohmann::json{{"colours", {{1, 2, 0}}}},
          nlohmann::json{{"colours", nlohmann::json(9, {0.5, 0.5, 0.5})}}}) {
        JsonObject bad(bad_json, "/materials/0/chermain2020", "scene.json");
        try {
            read_glint_params(*find_glint_model("chermain2020"), bad, desc);
            ADD_FAILURE() << "accepted " << bad_json.dump();
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("colours"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace glintlab
