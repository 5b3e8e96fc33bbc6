// Tests of the explicit ground truth (explicit.h): exact statistics of the
// generated facets, determinism/tiling, radiometric convergence, bad input.
// Significance: every chi-square test fails below p = 1e-4 with fixed seeds
// (a correct generator fails one of the ~12 tests with probability ~1e-3).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/counting/exact_binomial.h"
#include "glintlab/glints/explicit/binomial_half.h"
#include "glintlab/glints/explicit/count_chi2.h"
#include "glintlab/glints/explicit/explicit.h"
#include "glintlab/glints/explicit/explicit_model.h"
#include "glintlab/glints/glint_reader.h"
#include "glintlab/glints/registry.h"
#include "glintlab/microfacet/chi2_test_util.h"
#include "glintlab/microfacet/microfacet.h"
#include "glintlab/scene/scene.h"

namespace glintlab {
namespace {

constexpr double kSignificance = 1e-4;

Footprint square(glm::vec2 uv, float side) {
    return Footprint{uv, glm::vec2(side, 0.0f), glm::vec2(0.0f, side)};
}

glm::vec3 dir(double theta_deg, double phi_deg) {
    const double t = theta_deg * std::numbers::pi / 180.0, p = phi_deg * std::numbers::pi / 180.0;
    return glm::vec3(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)),
                     float(std::cos(t)));
}

TEST(ExplicitBinomial, HalfSamplerMatchesExactPmf) {
    // popcount branch (n <= 256) and BTRS (n > 256) up to n = 1e10.
    for (int64_t n : {int64_t(7), int64_t(200), int64_t(257), int64_t(1000), int64_t(1000000),
                      int64_t(1000000000), int64_t(10000000000)}) {
        Pcg32 rng(uint64_t(n), 17);
        std::vector<int64_t> draws(20000);
        for (auto& d : draws) d = explicit_gt::sample_binomial_half(n, rng);
        const auto r = explicit_gt::count_chi2(draws, double(n), 0.5);
        EXPECT_GT(r.p_value, kSignificance) << "n = " << n << ": " << r.describe();
    }
}

TEST(ExplicitField, NormalsFollowProjectedAreaDensity) {
    // All facets of one whole tile (exactly N of them): their normals against
    // D(m)(m·n), Beckmann/GGX, isotropic and anisotropic.
    struct Case {
        NdfType ndf;
        float ax, ay;
    };
    for (const Case c : {Case{NdfType::Beckmann, 0.3f, 0.3f}, Case{NdfType::GGX, 0.2f, 0.5f},
                         Case{NdfType::Beckmann, 0.6f, 0.15f}, Case{NdfType::GGX, 0.4f, 0.4f}}) {
        ExplicitFacetField field;
        field.ndf = c.ndf;
        field.alpha_x = c.ax;
        field.alpha_y = c.ay;
        field.log_density = std::log(300000.0);
        field.seed = 3;
        std::vector<glm::vec3> normals;
        std::vector<double> cells(40 * 40, 0.0);
        const uint64_t n =
            for_each_explicit_facet(field, square({0.5f, 0.5f}, 1.0f), [&](const ExplicitFacet& f) {
                normals.push_back(f.m);
                // 40 x 40 cells do not align with the quadtree (2^k) cells.
                cells[size_t(f.uv.y * 40.0f) * 40 + size_t(f.uv.x * 40.0f)] += 1.0;
            });
        ASSERT_EQ(n, explicit_facets_per_tile(field));  // the unit tile holds exactly N
        // Spatial uniformity: the cell counts of N i.i.d. uniform facets are
        // multinomial; Pearson's statistic has 1599 degrees of freedom.
        double chi2 = 0.0;
        const double expected = double(n) / double(cells.size());
        for (double c : cells) chi2 += (c - expected) * (c - expected) / expected;
        const double p_space = boost::math::gamma_q(0.5 * 1599.0, 0.5 * chi2);
        EXPECT_GT(p_space, kSignificance) << "spatial chi2 = " << chi2;
        size_t next = 0;
        testing::Chi2Config cfg;
        cfg.n_cos = 32;
        cfg.n_phi = 64;
        cfg.full_sphere = false;
        cfg.samples = long(normals.size());
        const int id = c.ndf == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN;
        const auto r = testing::chi2_test(
            [&](glm::vec3 m) { return shader::D_Microfacet(id, m, c.ax, c.ay) * m.z; },
            [&](Pcg32&) -> std::optional<glm::vec3> { return normals[next++]; }, cfg);
        EXPECT_GT(r.p_value, kSignificance) << r.describe();
        EXPECT_NEAR(r.pdf_mass, 1.0, 2e-3);  // D(m)(m·n) is normalised
    }
}

TEST(ExplicitField, CountsAreBinomialInSpaceAndDirection) {
    // Counts over independent fields (seeds) for fixed query geometries:
    // Binomial(N, a(A)) in space and Binomial(N, a(A) p_dir) in space ×
    // direction, p_dir by quadrature (explicit_direction_probability). One
    // footprint straddles the tile corner (tiling keeps the law).
    ExplicitFacetField field;
    field.log_density = std::log(1.0e6);
    field.alpha_x = 0.3f;
    field.alpha_y = 0.2f;
    const double N = double(explicit_facets_per_tile(field));
    const Footprint fps[] = {
        Footprint{{0.3f, 0.7f}, {0.04f, 0.01f}, {-0.01f, 0.03f}},
        Footprint{{1.0f, 2.0f}, {0.03f, 0.0f}, {0.0f, 0.04f}},  // corner of 4 tiles
    };
    const glm::vec3 wo = dir(30, 10), wi = dir(35, 200);
    const float gamma = 6.0f * std::numbers::pi_v<float> / 180.0f;
    const double p_dir = explicit_direction_probability(field, wo, wi, gamma);
    for (const Footprint& fp : fps) {
        std::vector<int64_t> space, both;
        for (uint32_t s = 0; s < 1500; ++s) {
            field.seed = s;
            int64_t k = 0, kd = 0;
            const float cg = std::cos(gamma);
            for_each_explicit_facet(field, fp, [&](const ExplicitFacet& f) {
                ++k;
                const glm::vec3 r = 2.0f * glm::dot(wo, f.m) * f.m - wo;
                if (glm::dot(wo, f.m) > 0.0f && glm::dot(r, wi) >= cg) ++kd;
            });
            EXPECT_EQ(uint64_t(kd), explicit_count(field, fp, wo, wi, gamma));
            space.push_back(k);
            both.push_back(kd);
        }
        const double a = explicit_footprint_area(fp);
        const auto rs = explicit_gt::count_chi2(space, N, a);
        const auto rd = explicit_gt::count_chi2(both, N, a * p_dir);
        EXPECT_GT(rs.p_value, kSignificance) << "space: " << rs.describe();
        EXPECT_GT(rd.p_value, kSignificance) << "space x direction: " << rd.describe();
        EXPECT_GT(rd.expected_mean, 10.0);  // the test has power
    }
}

TEST(ExplicitField, DeterministicOverlappingFootprintsAndTiling) {
    ExplicitFacetField field;
    field.log_density = std::log(2.0e7);
    field.seed = 11;
    const Footprint big = square({0.5f, 0.5f}, 0.01f);
    std::map<std::pair<float, float>, glm::vec3> all;
    const uint64_t n_big = for_each_explicit_facet(field, big, [&](const ExplicitFacet& f) {
        all[{f.uv.x, f.uv.y}] = f.m;
    });
    ASSERT_EQ(all.size(), n_big);
    ASSERT_GT(n_big, 1000u);
    // The four quarters partition the big footprint (half-open convention)
    // and enumerate identical facets.
    uint64_t sum = 0;
    for (float dx : {-0.0025f, 0.0025f})
        for (float dy : {-0.0025f, 0.0025f})
            sum += for_each_explicit_facet(field, square({0.5f + dx, 0.5f + dy}, 0.005f),
                                           [&](const ExplicitFacet& f) {
                                               const auto it = all.find({f.uv.x, f.uv.y});
                                               ASSERT_NE(it, all.end());
                                               EXPECT_EQ(it->second, f.m);
                                           });
    EXPECT_EQ(sum, n_big);
    // A rotated footprint inside the big one sees a subset; one tile away
    // (period 1) the same facets, shifted.
    for_each_explicit_facet(field, Footprint{{0.5f, 0.5f}, {0.004f, 0.003f}, {-0.003f, 0.004f}},
                            [&](const ExplicitFacet& f) {
                                ASSERT_TRUE(all.count({f.uv.x, f.uv.y}));
                            });
    // Same tile-local parallelogram → the same facets in the same order.
    std::vector<ExplicitFacet> base, moved;
    for_each_explicit_facet(field, big, [&](const ExplicitFacet& f) { base.push_back(f); });
    const uint64_t shifted = for_each_explicit_facet(
        field, square({3.5f, -1.5f}, 0.01f), [&](const ExplicitFacet& f) { moved.push_back(f); });
    ASSERT_EQ(moved.size(), base.size());
    for (size_t i = 0; i < base.size(); ++i) {
        EXPECT_NEAR(moved[i].uv.x - base[i].uv.x, 3.0f, 1e-6f);
        EXPECT_NEAR(moved[i].uv.y - base[i].uv.y, -2.0f, 1e-6f);
        EXPECT_EQ(moved[i].m, base[i].m);
    }
    EXPECT_EQ(shifted, n_big);
}

// A thin footprint along a silhouette: its bounding box spans 258 x 114
// tiles (29 412, over the 4096-tile limit, which it used to fail) while it
// touches a few hundred. It visits exactly the facets inside it: those of a
// brute-force pass over every tile of the bounding box.
TEST(ExplicitField, ThinFootprintAcrossManyTilesVisitsTheFacetsInside) {
    ExplicitFacetField field;
    field.log_density = std::log(40.0);
    field.seed = 5;
    const glm::dvec2 c(0.3, 0.7), e1(257.0, 113.0);
    const glm::dvec2 e2 = glm::dvec2(-e1.y, e1.x) * (0.02 / glm::length(e1));  // 0.02 wide
    const Footprint thin{glm::vec2(c), glm::vec2(e1), glm::vec2(e2)};
    const glm::dvec2 fc(thin.uv), f1(thin.duvdx), f2(thin.duvdy);  // as stored (float)
    const double det = f1.x * f2.y - f1.y * f2.x;
    const auto inside = [&](glm::vec2 uv) {
        const glm::dvec2 d = glm::dvec2(uv) - fc;
        const double s = (f2.y * d.x - f2.x * d.y) / det, t = (-f1.y * d.x + f1.x * d.y) / det;
        return s >= -0.5 && s < 0.5 && t >= -0.5 && t < 0.5;
    };
    uint64_t count = 0;
    double sum_u = 0.0;
    const uint64_t visited = for_each_explicit_facet(field, thin, [&](const ExplicitFacet& f) {
        EXPECT_TRUE(inside(f.uv)) << f.uv.x << " " << f.uv.y;
        ++count, sum_u += f.uv.x;
    });
    EXPECT_EQ(visited, count);
    uint64_t brute = 0;
    double brute_u = 0.0;
    for (int ty = -57; ty <= 57; ++ty)
        for (int tx = -129; tx <= 129; ++tx)
            for_each_explicit_facet(field,
                                    Footprint{{tx + 0.5f, ty + 0.5f}, {1.0f, 0.0f}, {0.0f, 1.0f}},
                                    [&](const ExplicitFacet& f) {
                                        if (inside(f.uv)) ++brute, brute_u += f.uv.x;
                                    });
    EXPECT_EQ(count, brute);
    EXPECT_NEAR(sum_u, brute_u, 1e-6 * (1.0 + std::abs(brute_u)));
    // N a(A) = 40 * 280.7 * 0.02 = 225 expected facets.
    EXPECT_GT(count, 150u);
    EXPECT_LT(count, 300u);
    // A footprint that does touch more than 4096 tiles still fails, by name.
    field.log_density = 0.0;  // 1 facet per tile: under max_facets_per_footprint
    try {
        for_each_explicit_facet(field, square({0.5f, 0.5f}, 70.0f), [](const ExplicitFacet&) {});
        FAIL() << "no error above 4096 touched tiles";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("touches 5041 uv tiles (more than 4096"),
                  std::string::npos)
            << e.what();
    }
}

// over_budget "subsample": a footprint above the budget is replaced by one
// of K x K equal parts, which partition its facets (so the mean of the
// parts' estimates is the footprint's: unbiased), chosen uniformly.
TEST(ExplicitField, OverBudgetFootprintEnumeratesOneOfItsEqualParts) {
    ExplicitFacetField field;
    field.log_density = std::log(1.0e6);
    field.seed = 3;
    field.max_facets_per_footprint = 1000.0;
    const Footprint fp{{0.37f, 0.61f}, {0.05f, 0.01f}, {-0.02f, 0.06f}};  // 3200 facets: K = 2
    const auto noop = [](const ExplicitFacet&) {};
    EXPECT_EQ(explicit_enumerated_footprint(field, fp).duvdx, fp.duvdx);  // off: unchanged
    EXPECT_THROW(for_each_explicit_facet(field, fp, noop), Error);
    field.subsample_over_budget = true;
    std::vector<Footprint> parts;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
            parts.push_back(
                Footprint{fp.uv + (0.5f * i - 0.25f) * fp.duvdx + (0.5f * j - 0.25f) * fp.duvdy,
                          0.5f * fp.duvdx, 0.5f * fp.duvdy});
    uint64_t sum = 0;
    for (const Footprint& p : parts) sum += for_each_explicit_facet(field, p, noop);
    field.max_facets_per_footprint = 1e6;
    const uint64_t whole = for_each_explicit_facet(field, fp, noop);
    EXPECT_EQ(sum, whole);  // the parts partition the footprint's facets
    EXPECT_GT(whole, 3000u);
    field.max_facets_per_footprint = 1000.0;
    // Jittered centres pick the parts uniformly: 4000 draws, 1000 expected
    // each (sd 27), bounds at 5 sd.
    int hits[4] = {0, 0, 0, 0};
    for (int n = 0; n < 4000; ++n) {
        Footprint jittered = fp;
        jittered.uv += glm::vec2(1e-4f * float(n % 63), 1e-4f * float(n / 63));
        const Footprint part = explicit_enumerated_footprint(field, jittered);
        EXPECT_EQ(part.duvdx, 0.5f * fp.duvdx);
        int found = -1;
        for (int k = 0; k < 4; ++k)
            if (glm::length(part.uv - (parts[size_t(k)].uv + (jittered.uv - fp.uv))) < 1e-6f)
                found = k;
        ASSERT_GE(found, 0);
        ++hits[found];
    }
    for (int k = 0; k < 4; ++k) {
        EXPECT_GT(hits[k], 865) << k;
        EXPECT_LT(hits[k], 1135) << k;
    }
    // Within the budget, the footprint itself.
    field.max_facets_per_footprint = 1e4;
    EXPECT_EQ(explicit_enumerated_footprint(field, fp).duvdx, fp.duvdx);
}

TEST(ExplicitField, BillionFacetsPerUnitAreaOnTinyFootprints) {
    ExplicitFacetField field;
    field.log_density = std::log(1.0e9);
    EXPECT_EQ(explicit_facets_per_tile(field), 1000000000u);
    // 1e-7 uv² holds 100 facets in expectation: counts over 400 disjoint
    // footprints of one field are Binomial(N, 1e-7) up to the (negligible)
    // correlation of a fixed total.
    std::vector<int64_t> counts;
    const float side = float(std::sqrt(1e-7));
    for (int i = 0; i < 400; ++i) {
        const Footprint fp =
            square({0.1f + 0.002f * float(i % 20), 0.2f + 0.003f * float(i / 20)}, side);
        counts.push_back(int64_t(for_each_explicit_facet(field, fp, [&](const ExplicitFacet& f) {
            ASSERT_LE(std::abs(f.uv.x - fp.uv.x), 0.5f * side + 1e-6f);
            ASSERT_LE(std::abs(f.uv.y - fp.uv.y), 0.5f * side + 1e-6f);
        })));
    }
    const auto r = explicit_gt::count_chi2(counts, 1e9, double(side) * side);
    EXPECT_GT(r.p_value, kSignificance) << r.describe();
}

TEST(ExplicitRadiometry, FootprintNdfConvergesToSmoothNdf) {
    // Mean D_P over independent fields → the γ-cone average of D (exact
    // expectation by quadrature) and, γ = 3°, to D(h) itself within the
    // cone's smoothing (O(γ²) times the relative curvature of D, < 1 % here).
    // 32 footprints × ~3e3 expected facets in the cone: relative std of the
    // mean ~ 1/sqrt(1e5) = 0.32 %; 1.5 % is > 4.5 sigma.
    ExplicitFacetField field;
    field.ndf = NdfType::GGX;
    field.alpha_x = 0.25f;
    field.alpha_y = 0.4f;
    field.log_density = std::log(2.0e9);
    field.max_facets_per_footprint = 1e8;
    const float gamma = 3.0f * std::numbers::pi_v<float> / 180.0f;
    const glm::vec3 wo = dir(40, 30), wi = dir(20, 160);
    const glm::vec3 h = glm::normalize(wo + wi);
    const double p_dir = explicit_direction_probability(field, wo, wi, gamma);
    const double cos_ih = glm::dot(wi, h);
    const double expected = 4.0 * cos_ih * p_dir / (explicit_cone_solid_angle(gamma) * h.z);
    const double d = shader::D_GGX(h, field.alpha_x, field.alpha_y);
    EXPECT_NEAR(expected / d, 1.0, 1e-2);
    const Footprint fp = square({0.25f, 0.25f}, 0.0224f);
    const double expected_in_cone = 2e9 * 0.0224 * 0.0224 * p_dir;
    ASSERT_GT(expected_in_cone, 2500.0);
    double mean = 0.0;
    const int M = 32;
    for (int s = 0; s < M; ++s) {
        field.seed = uint32_t(s);
        mean += explicit_footprint_ndf(field, fp, wo, wi, gamma) / M;
    }
    EXPECT_NEAR(mean / expected, 1.0, 0.015) << "expected in cone " << expected_in_cone;
}

TEST(ExplicitRadiometry, EnvironmentRadianceConvergesToSmoothBrdf) {
    // 1/(N a) Σ w F L_env over ~2.5e5 facets vs the smooth reflected radiance
    // ∫ F G2 D L / (4 wo·n) dwi (midpoint quadrature, 1024² cells in
    // (cos θ, φ)). Relative std of the estimate ~ CV(w L)/sqrt(2.5e5) < 0.4 %.
    ExplicitFacetField field;
    field.ndf = NdfType::Beckmann;
    field.alpha_x = 0.35f;
    field.alpha_y = 0.2f;
    field.log_density = std::log(2.5e5);
    field.seed = 5;
    const auto env = [](glm::vec3 d) {
        return glm::vec3(1.0f + 0.8f * d.x, 1.0f + 0.5f * d.y * d.y, 0.3f + d.z * d.z);
    };
    const auto fresnel = [](float c) { return glm::vec3(shader::F_Schlick(0.5f, c)); };
    for (const glm::vec3 wo : {dir(10, 0), dir(55, 70)}) {
        const glm::vec3 L =
            explicit_environment_radiance(field, square({0.5f, 0.5f}, 1.0f), wo, env, fresnel);
        glm::dvec3 ref(0.0);
        const int n = 1024;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double ct = (i + 0.5) / n, ph = 2.0 * std::numbers::pi * (j + 0.5) / n;
                const glm::vec3 wi = testing::direction_from(ct, ph);
                const glm::vec3 h = glm::normalize(wo + wi);
                const float f = shader::F_Schlick(0.5f, glm::dot(wo, h)) *
                                shader::G2_SmithCorrelated(shader::NDF_BECKMANN, wo, wi,
                                                           field.alpha_x, field.alpha_y) *
                                shader::D_Beckmann(h, field.alpha_x, field.alpha_y) / (4.0f * wo.z);
                ref += glm::dvec3(f * env(wi)) * (2.0 * std::numbers::pi / (double(n) * n));
            }
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(L[c] / ref[c], 1.0, 0.012) << "channel " << c;
    }
}

TEST(ExplicitInput, BadInputIsAClearError) {
    ExplicitFacetField field;
    const Footprint fp = square({0.5f, 0.5f}, 0.01f);
    const auto noop = [](const ExplicitFacet&) {};
    field.log_density = 40.0;
    EXPECT_THROW(for_each_explicit_facet(field, fp, noop), Error);
    field.log_density = 20.0;
    field.alpha_x = 0.0f;
    EXPECT_THROW(for_each_explicit_facet(field, fp, noop), Error);
    field.alpha_x = 0.3f;
    try {
        for_each_explicit_facet(field, square({0.5f, 0.5f}, 0.5f), noop);  // 1.2e8 facets
        FAIL() << "no error above max_facets_per_footprint";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("max_facets_per_footprint"), std::string::npos);
    }
    EXPECT_THROW(for_each_explicit_facet(field, square({NAN, 0.5f}, 0.01f), noop), Error);
    // At uv ~1e16 a tile step of 1 did not move a double: the walk never ended.
    try {
        for_each_explicit_facet(field, square({1e16f, 0.5f}, 0.01f), noop);
        FAIL() << "no error at uv 1e16";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("must stay below 1e+09"), std::string::npos)
            << e.what();
    }
    EXPECT_NO_THROW(for_each_explicit_facet(field, square({-1e6f, 1e6f}, 1e-3f), noop));
    // Degenerate footprints hold no facets.
    EXPECT_EQ(
        for_each_explicit_facet(field, Footprint{{0.5f, 0.5f}, {0.1f, 0.0f}, {0.2f, 0.0f}}, noop),
        0u);

    const auto read = [](const nlohmann::json& j, float log_density) {
        GlintDesc desc;
        desc.log_density = log_density;
        JsonObject block(j, "/materials/0/glint/explicit", "scene.json");
        read_glint_params(*find_glint_model("explicit"), block, desc);
        return desc;
    };
    EXPECT_NO_THROW(read(nlohmann::json{{"gamma_deg", 2.0}}, 20.0f));
    EXPECT_THROW(read(nlohmann::json{{"gamma_deg", 10.0}}, 20.0f), Error);
    EXPECT_THROW(read(nlohmann::json{{"gamma", 1.0}}, 20.0f), Error);
    EXPECT_THROW(read(nlohmann::json{{"max_facets_per_footprint", 0.0}}, 20.0f), Error);
    try {
        read(nlohmann::json::object(), 45.0f);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("log_density"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace glintlab
