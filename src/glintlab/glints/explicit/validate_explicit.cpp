#include "glintlab/glints/explicit/validate_explicit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "glintlab/core/rng.h"
#include "glintlab/glints/explicit/count_chi2.h"
#include "glintlab/glints/explicit/explicit.h"
#include "glintlab/glints/validation_suites.h"
#include "glintlab/microfacet/microfacet.h"

namespace glintlab {
namespace {

struct Geometry {
    const char* name;
    NdfType ndf;
    float ax, ay;
    float wo_theta, wo_phi, wi_theta, wi_phi;  // degrees
    float gamma_deg;
    glm::vec2 uv;  // footprint centre (one straddles a tile corner)
};

constexpr Geometry kGeometries[] = {
    {"beckmann 0.3 off-specular", NdfType::Beckmann, 0.3f, 0.3f, 30, 10, 35, 200, 6, {0.3f, 0.7f}},
    {"ggx 0.2x0.5 oblique", NdfType::GGX, 0.2f, 0.5f, 60, 45, 20, 250, 3, {0.6f, 0.2f}},
    {"beckmann 0.5x0.15 wide", NdfType::Beckmann, 0.5f, 0.15f, 10, 0, 70, 180, 6, {0.5f, 0.5f}},
    {"ggx 0.1 mirror peak", NdfType::GGX, 0.1f, 0.1f, 45, 90, 45, 270, 1, {0.25f, 0.8f}},
    {"ggx 0.6 grazing", NdfType::GGX, 0.6f, 0.6f, 80, 0, 80, 180, 6, {0.9f, 0.4f}},
    {"beckmann 0.3 tile corner", NdfType::Beckmann, 0.3f, 0.3f, 5, 0, 5, 180, 2, {2.0f, -1.0f}},
};

glm::vec3 dir(double theta_deg, double phi_deg) {
    const double t = theta_deg * std::numbers::pi / 180.0, p = phi_deg * std::numbers::pi / 180.0;
    return glm::vec3(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)),
                     float(std::cos(t)));
}

// A rotated, sheared parallelogram of the given area centred at uv.
Footprint footprint(glm::vec2 uv, double area) {
    const double s = std::sqrt(area);
    const glm::dvec2 e1 = s * glm::dvec2(1.2, 0.3), e2 = s * glm::dvec2(-0.25, 0.9);
    const double det = e1.x * e2.y - e1.y * e2.x;  // 1.155 s²
    const double k = std::sqrt(area / det);
    return Footprint{uv, glm::vec2(k * e1), glm::vec2(k * e2)};
}

ExplicitFacetField field_of(const Geometry& g, double n, uint32_t seed) {
    ExplicitFacetField f;
    f.ndf = g.ndf;
    f.alpha_x = g.ax;
    f.alpha_y = g.ay;
    f.log_density = std::log(n);
    f.seed = seed;
    f.max_facets_per_footprint = 1e9;
    return f;
}

}  // namespace

ValidationReport validate_explicit(const ExplicitValidationOptions& o) {
    ValidationReport report;
    report.suite = "explicit";
    const uint32_t base_seed = uint32_t(mix_bits(o.seed) >> 40);
    nlohmann::json geoms = nlohmann::json::array();
    std::string text = fmt::format("{:<28} {:>9} {:>10} {:>10} {:>10} {:>11}\n", "geometry",
                                   "p_dir", "p(space)", "p(dir)", "D_P err", "D_P/D(h)");
    double p_min = 1.0, rel_max = 0.0;
    int tests = 0;
    int64_t nan_count = 0;
    for (const Geometry& g : kGeometries) {
        const glm::vec3 wo = dir(g.wo_theta, g.wo_phi), wi = dir(g.wi_theta, g.wi_phi);
        const float gamma = g.gamma_deg * std::numbers::pi_v<float> / 180.0f;
        const double N = 1.0e6;
        const ExplicitFacetField probe = field_of(g, N, 0);
        const double p_dir = explicit_direction_probability(probe, wo, wi, gamma);
        // Counts: λ = N a p_dir ≈ count_mean.
        const double area = std::min(0.05, o.count_mean / (N * p_dir));
        const Footprint fp = footprint(g.uv, area);
        const double a = explicit_footprint_area(fp);
        std::vector<int64_t> space, both;
        for (int s = 0; s < o.count_footprints; ++s) {
            const ExplicitFacetField f = field_of(g, N, base_seed + uint32_t(s));
            int64_t k = 0, kd = 0;
            const float cg = std::cos(gamma);
            for_each_explicit_facet(f, fp, [&](const ExplicitFacet& x) {
                ++k;
                const glm::vec3 r = 2.0f * glm::dot(wo, x.m) * x.m - wo;
                if (glm::dot(wo, x.m) > 0.0f && glm::dot(r, wi) >= cg) ++kd;
            });
            space.push_back(k);
            both.push_back(kd);
        }
        const double Nt = double(explicit_facets_per_tile(probe));
        const auto rs = explicit_gt::count_chi2(space, Nt, a);
        const auto rd = explicit_gt::count_chi2(both, Nt, a * p_dir);
        p_min = std::min({p_min, rs.p_value, rd.p_value});
        tests += 2;
        // Convergence of D_P: convergence_count expected facets in the cone.
        const double Nc = 1.0e8;
        const ExplicitFacetField probe_c = field_of(g, Nc, 0);
        const double pc = explicit_direction_probability(probe_c, wo, wi, gamma);
        const Footprint fpc = footprint(g.uv, o.convergence_count / (Nc * pc));
        const glm::vec3 h = glm::normalize(wo + wi);
        const double expected =
            4.0 * glm::dot(wi, h) * pc / (explicit_cone_solid_angle(gamma) * h.z);
        double mean = 0.0;
        for (int s = 0; s < o.convergence_footprints; ++s) {
            const float d = explicit_footprint_ndf(field_of(g, Nc, base_seed + 7919u * uint32_t(s)),
                                                   fpc, wo, wi, gamma);
            if (!std::isfinite(d)) ++nan_count;
            mean += d / o.convergence_footprints;
        }
        const double rel = std::abs(mean / expected - 1.0);
        rel_max = std::max(rel_max, rel);
        const double d_smooth = shader::D_Microfacet(
            g.ndf == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN, h, g.ax, g.ay);
        text += fmt::format("{:<28} {:>9.3g} {:>10.3g} {:>10.3g} {:>10.2e} {:>11.4f}\n", g.name,
                            p_dir, rs.p_value, rd.p_value, rel, expected / d_smooth);
        geoms.push_back({{"name", g.name},
                         {"p_dir", p_dir},
                         {"count_area", a},
                         {"space_chi2", rs.describe()},
                         {"direction_chi2", rd.describe()},
                         {"convergence_rel_err", rel},
                         {"cone_mean_over_smooth_D", expected / d_smooth}});
    }
    // Environment radiance vs the smooth BRDF's reflected radiance.
    nlohmann::json env_rows = nlohmann::json::array();
    const auto env = [](glm::vec3 d) {
        return glm::vec3(1.0f + 0.8f * d.x, 1.0f + 0.5f * d.y * d.y, 0.3f + d.z * d.z);
    };
    for (const Geometry& g : {kGeometries[0], kGeometries[1], kGeometries[4]}) {
        const glm::vec3 wo = dir(g.wo_theta, g.wo_phi);
        const ExplicitFacetField f = field_of(g, o.environment_facets, base_seed + 17u);
        const glm::vec3 L = explicit_environment_radiance(
            f, Footprint{{0.5f, 0.5f}, {1.0f, 0.0f}, {0.0f, 1.0f}}, wo, env);
        const int id = g.ndf == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN;
        glm::dvec3 ref(0.0);
        const int n = 1024;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double ct = (i + 0.5) / n, ph = 2.0 * std::numbers::pi * (j + 0.5) / n;
                const double st = std::sqrt(1.0 - ct * ct);
                const glm::vec3 w(float(st * std::cos(ph)), float(st * std::sin(ph)), float(ct));
                const glm::vec3 h = glm::normalize(wo + w);
                const double v = shader::G2_SmithCorrelated(id, wo, w, g.ax, g.ay) *
                                 shader::D_Microfacet(id, h, g.ax, g.ay) / (4.0 * wo.z);
                ref += glm::dvec3(env(w)) * v * (2.0 * std::numbers::pi / (double(n) * n));
            }
        double rel = 0.0;
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(L[c])) ++nan_count;
            rel = std::max(rel, std::abs(L[c] / ref[c] - 1.0));
        }
        rel_max = std::max(rel_max, rel);
        text += fmt::format("environment, {:<15} rel. error {:.2e}\n", g.name, rel);
        env_rows.push_back({{"name", g.name}, {"rel_err", rel}});
    }
    // Robustness: random directions (grazing included), shapes and degenerate footprints.
    Pcg32 rng(o.seed, 0xe1);
    for (int q = 0; q < o.robustness_queries; ++q) {
        const Geometry& g = kGeometries[size_t(q) % std::size(kGeometries)];
        const ExplicitFacetField f = field_of(g, 1.0e7, uint32_t(q));
        const float z1 = rng.next_float(), z2 = rng.next_float();
        const glm::vec3 wo = glm::normalize(
            glm::vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, z1 * z1 + 1e-7f));
        const glm::vec3 wi =
            glm::normalize(glm::vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, z2 - 0.1f));
        const float scale = std::ldexp(1.0f, -int(rng.next_uint(12)));
        glm::vec2 e1(rng.next_float() - 0.5f, rng.next_float() - 0.5f);
        glm::vec2 e2 =
            q % 7 == 0 ? 2.0f * e1 : glm::vec2(rng.next_float() - 0.5f, rng.next_float() - 0.5f);
        const Footprint fp{
            glm::vec2(rng.next_float() * 4.0f - 2.0f, rng.next_float() * 4.0f - 2.0f),
            e1 * scale * 0.02f, e2 * scale * 0.02f};
        const float d = explicit_footprint_ndf(
            f, fp, wo, wi, 0.5f * std::numbers::pi_v<float> / 180.0f * float(1 + q % 12));
        const glm::vec3 L = explicit_environment_radiance(f, fp, wo, env);
        if (!std::isfinite(d) || !(d >= 0.0f)) ++nan_count;
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(L[c]) || !(L[c] >= 0.0f)) ++nan_count;
    }
    const double p_adj = std::min(1.0, p_min * tests);
    report.check("count_chi2_p_min", p_adj, ">", 0.001);
    report.check("convergence_rel_err_max", rel_max, "<=", 0.01);
    report.check("nan_count", double(nan_count), "==", 0.0);
    report.details["geometries"] = geoms;
    report.details["environment"] = env_rows;
    report.details["count_chi2_p_min_raw"] = p_min;
    report.details["count_tests"] = tests;
    report.text =
        text +
        fmt::format("count chi-square: min p = {:.3g} over {} tests (Bonferroni-adjusted {:.3g})\n",
                    p_min, tests, p_adj);
    return report;
}

// `glintlab validate explicit` (model_list.h).
ValidationSuiteRunner explicit_validation_suite() {
    return seeded_validation_suite<ExplicitValidationOptions, validate_explicit>();
}

}  // namespace glintlab
