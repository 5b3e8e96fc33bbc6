#include "glintlab/glints/jakob2014/jakob2014_experiments.h"

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "glintlab/core/error.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/explicit/explicit.h"
#include "glintlab/glints/glint_desc.h"
#include "glintlab/glints/jakob2014/jakob2014.h"
#include "glintlab/glints/registry.h"
#include "glintlab/microfacet/microfacet.h"

namespace glintlab::jakob2014 {
namespace {

NdfSpec spec_of(const QueryGeometry& g) {
    NdfSpec s;
    s.ndf = g.ndf;
    s.alpha_x = g.alpha_x;
    s.alpha_y = g.alpha_y;
    return s;
}

Model model_of(const QueryGeometry& g, uint32_t seed, double epsilon) {
    Model m;
    m.table = &ndf_integral_table(spec_of(g));
    m.particles = std::llround(std::exp(g.log_density));
    m.gamma = g.gamma_deg * std::numbers::pi / 180.0;
    m.epsilon = epsilon;
    m.max_depth = 20;
    m.seed = seed;
    m.query_area = std::abs(g.e1.x * g.e2.y - g.e1.y * g.e2.x);
    m.query_solid_angle = cone_solid_angle(m.gamma) /
                          (4.0 * glm::dot(glm::normalize(g.wi), glm::normalize(g.wi + g.wo)));
    return m;
}

}  // namespace

CountChi2 count_chi2(const QueryGeometry& g, int footprints, uint64_t seed) {
    CountChi2 r;
    const NdfSpec spec = spec_of(g);
    const double area = std::abs(g.e1.x * g.e2.y - g.e1.y * g.e2.x);
    const double p =
        expected_fraction(spec, area, g.wi, g.wo, g.gamma_deg * std::numbers::pi / 180.0);
    const int64_t n = std::llround(std::exp(g.log_density));
    r.expected_mean = double(n) * p;
    Pcg32 rng(seed, 0x6a616b6fu);
    std::vector<int64_t> counts(size_t(footprints), 0);
    double sum = 0.0;
    for (int k = 0; k < footprints; ++k) {
        Model m = model_of(g, rng.next_uint(), 0.0);
        UvParallelogram q;
        q.center = {rng.next_double(), rng.next_double()};
        if (g.at_tile_corner) q.center = {0.0, 0.0};
        q.e1 = g.e1;
        q.e2 = g.e2;
        const double c = query_count(m, q, g.wi, g.wo, nullptr).count;
        if (c != std::floor(c)) ++r.non_integer;
        counts[size_t(k)] = std::llround(c);
        sum += c;
    }
    r.observed_mean = sum / footprints;
    // Bins k = 0, 1, ... with the tail pooled; adjacent bins merged until each expects >= 5.
    const boost::math::binomial_distribution<double> law(double(n), p);
    int64_t kmax = 0;
    for (int64_t c : counts) kmax = std::max(kmax, c);
    const int64_t top =
        std::max<int64_t>(kmax, int64_t(r.expected_mean + 10.0 * std::sqrt(r.expected_mean + 1.0)));
    std::vector<double> obs(size_t(top + 1), 0.0), expv(size_t(top + 1), 0.0);
    for (int64_t c : counts) obs[size_t(c)] += 1.0;
    double acc = 0.0;
    for (int64_t k = 0; k < top; ++k) {
        expv[size_t(k)] = boost::math::pdf(law, double(k)) * footprints;
        acc += expv[size_t(k)];
    }
    expv[size_t(top)] = std::max(0.0, footprints - acc);  // P(X >= top)
    std::vector<std::pair<double, double>> bins;
    double be = 0.0, bo = 0.0;
    for (size_t k = 0; k < expv.size(); ++k) {
        be += expv[k];
        bo += obs[k];
        if (be >= 5.0) {
            bins.emplace_back(be, bo);
            be = bo = 0.0;
        }
    }
    if (be > 0.0 || bo > 0.0) {
        if (bins.empty())
            bins.emplace_back(be, bo);
        else {
            bins.back().first += be;
            bins.back().second += bo;
        }
    }
    for (const auto& [e, o] : bins) r.chi2 += (o - e) * (o - e) / e;
    r.dof = int(bins.size()) - 1;
    r.p_value = r.dof > 0 ? boost::math::gamma_q(0.5 * r.dof, 0.5 * r.chi2) : 1.0;
    return r;
}

ConvergenceResult convergence(const QueryGeometry& g, double expected_count, int footprints,
                              uint64_t seed, double epsilon) {
    ConvergenceResult r;
    const NdfSpec spec = spec_of(g);
    const double gamma = g.gamma_deg * std::numbers::pi / 180.0;
    const int64_t n = std::llround(std::exp(g.log_density));
    const double p_unit = expected_fraction(spec, 1.0, g.wi, g.wo, gamma);
    const double area = expected_count / (double(n) * p_unit);
    const double side = std::sqrt(area);
    const glm::dvec3 h = glm::normalize(g.wi + g.wo);
    QueryGeometry gg = g;
    gg.e1 = {side, 0.0};
    gg.e2 = {0.0, side};
    r.expected_count = expected_count;
    r.smooth_ndf = spec.density(h) / h.z;
    Pcg32 rng(seed, 0x636f6e76u);
    double sum = 0.0, sum2 = 0.0;
    Model m0 = model_of(gg, 0u, epsilon);
    const double scale = count_to_ndf(m0, area, g.wi, h);
    r.cone_ndf = p_unit * area * double(n) * scale;
    for (int k = 0; k < footprints; ++k) {
        Model m = m0;
        m.seed = rng.next_uint();
        UvParallelogram q;
        q.center = {rng.next_double(), rng.next_double()};
        q.e1 = gg.e1;
        q.e2 = gg.e2;
        const double d = query_count(m, q, g.wi, g.wo, nullptr).count * scale;
        sum += d;
        sum2 += d * d;
    }
    r.mean_ndf = sum / footprints;
    const double var = std::max(0.0, sum2 / footprints - r.mean_ndf * r.mean_ndf);
    r.std_err = std::sqrt(var / footprints) / r.mean_ndf;
    r.rel_err_smooth = std::abs(r.mean_ndf / r.smooth_ndf - 1.0);
    r.rel_err_cone = std::abs(r.mean_ndf / r.cone_ndf - 1.0);
    return r;
}

std::vector<Table1Row> table1_statistics(int pixels, uint64_t seed) {
    struct Setting {
        const char* scene;
        double paper_nodes, paper_count;
        double log_density;  // ln N
        double gamma_deg;
        float alpha;
        double coverage;  // fraction of the 768 x 768 image the glinty surface covers
    };
    // 002 Table 1: SPHERE LIGHTS N = 1e9, γ = 0.5°, α = 0.1, 43 nodes, 0.66 particles;
    // TWISTED TORUS N = 1e5..1e8, γ = 1°, α = 0.81..0.03, 9.6-36.6 nodes, 3e-6..0.53 particles.
    const Setting settings[] = {
        {"SPHERE LIGHTS (N=1e9, a=0.1, g=0.5)", 43.0, 0.66, std::log(1e9), 0.5, 0.1f, 0.6},
        {"TWISTED TORUS (N=1e5, a=0.81, g=1)", 9.6, 3e-6, std::log(1e5), 1.0, 0.81f, 0.3},
        {"TWISTED TORUS (N=1e8, a=0.03, g=1)", 36.6, 0.53, std::log(1e8), 1.0, 0.03f, 0.3},
    };
    std::vector<Table1Row> rows;
    for (const Setting& s : settings) {
        GlintDesc desc;
        desc.model_id = GlintModelId::Jakob2014;
        desc.ndf = NdfType::Beckmann;
        desc.alpha_x = desc.alpha_y = s.alpha;
        desc.log_density = float(s.log_density);
        Jakob2014Params p;
        p.gamma_deg = float(s.gamma_deg);
        // The pixel footprint: the surface's uv square spread over coverage ×
        // 768² pixels, scaled by 1/spp = 1/256 in area (Mitsuba 0.5 scales ray
        // differentials by 1/sqrt(spp); the paper renders 256 spp).
        const double area = 1.0 / (s.coverage * 768.0 * 768.0) / 256.0;
        p.query_area = area;  // the "short prior run": every query here has this area
        desc.params = p;
        Table1Row row;
        row.scene = s.scene;
        row.paper_nodes = s.paper_nodes;
        row.paper_count = s.paper_count;
        QueryStats& st = thread_stats();
        st = QueryStats{};
        Pcg32 rng(seed, 0x7461626cu);
        const double side = std::sqrt(area);
        for (int i = 0; i < pixels; ++i) {
            // View directions of a surface seen from all around (cosine-weighted),
            // light directions from the BRDF's importance sampling (the paths
            // that reach lights by MIS) — see docs/VALIDATION.md.
            const double r1 = rng.next_double(), r2 = rng.next_double();
            const double sr = std::sqrt(r1), ph = 2.0 * std::numbers::pi * r2;
            const glm::vec3 wo =
                glm::normalize(glm::vec3(float(sr * std::cos(ph)), float(sr * std::sin(ph)),
                                         float(std::sqrt(std::max(1e-4, 1.0 - r1)))));
            const auto wi = jakob2014_sample_wi(desc, wo, rng.next_float(),
                                                glm::vec2(rng.next_float(), rng.next_float()));
            if (!wi) continue;
            const double rot = rng.next_double() * std::numbers::pi;
            Footprint fp;
            fp.uv = glm::vec2(rng.next_float(), rng.next_float());
            fp.duvdx = glm::vec2(float(side * std::cos(rot)), float(side * std::sin(rot)));
            fp.duvdy = glm::vec2(float(-side * std::sin(rot)), float(side * std::cos(rot)));
            const glm::vec3 h = glm::normalize(wo + *wi);
            const float d = jakob2014_footprint_ndf(wo, *wi, h, fp, desc);
            if (!std::isfinite(d)) ++row.nan_count;
        }
        row.queries = st.queries;
        row.over_budget = st.over_budget;
        row.nodes = st.queries ? double(st.nodes) / double(st.queries) : 0.0;
        row.count = st.queries ? st.particles / double(st.queries) : 0.0;
        rows.push_back(row);
    }
    return rows;
}

}  // namespace glintlab::jakob2014

namespace glintlab::jakob2014 {

namespace {

// The two models on the same material: the `explicit` facet field and a
// jakob2014 glint description, each seeded per realization.
struct ComparedModels {
    ExplicitFacetField field;
    GlintDesc desc;
};

ComparedModels compared_models(int ndf, float alpha, double gamma_deg, double log_density) {
    ComparedModels m;
    m.field.ndf = ndf == shader::NDF_GGX ? NdfType::GGX : NdfType::Beckmann;
    m.field.alpha_x = m.field.alpha_y = alpha;
    // The glint material stores ln N as a float: give the field the same value.
    m.field.log_density = static_cast<double>(static_cast<float>(log_density));
    m.desc.model_id = GlintModelId::Jakob2014;
    m.desc.ndf = m.field.ndf;
    m.desc.alpha_x = m.desc.alpha_y = alpha;
    m.desc.log_density = static_cast<float>(log_density);
    Jakob2014Params params;
    params.gamma_deg = static_cast<float>(gamma_deg);
    m.desc.params = params;
    if (make_model(m.desc).particles != static_cast<int64_t>(explicit_facets_per_tile(m.field)))
        fail("jakob2014 vs explicit: the two models disagree on N at log density {}", log_density);
    return m;
}

// Per-realization first and second moments of both models -> the comparison
// (relative differences and their standard errors from the realizations).
ExplicitComparison summarize(const std::vector<glm::dvec2>& expl,
                             const std::vector<glm::dvec2>& jak,
                             const std::vector<glm::dvec2>& var = {}) {
    const double k = static_cast<double>(expl.size());
    glm::dvec2 se(0.0), se2(0.0), sj(0.0), sj2(0.0);
    for (size_t r = 0; r < expl.size(); ++r) {
        se += expl[r], se2 += expl[r] * expl[r];
        sj += jak[r], sj2 += jak[r] * jak[r];
    }
    ExplicitComparison out;
    out.mean_explicit = se.x / k;
    out.m2_explicit = se.y / k;
    out.mean_jakob = sj.x / k;
    out.m2_jakob = sj.y / k;
    out.mean_rel_err = std::abs(out.mean_jakob / out.mean_explicit - 1.0);
    out.m2_rel_err = std::abs(out.m2_jakob / out.m2_explicit - 1.0);
    const auto rel_se = [&](int i) {
        const double va =
            std::max(0.0, se2[i] / k - (se[i] / k) * (se[i] / k)) / std::max(1.0, k - 1.0);
        const double vb =
            std::max(0.0, sj2[i] / k - (sj[i] / k) * (sj[i] / k)) / std::max(1.0, k - 1.0);
        return std::sqrt(va + vb) / (se[i] / k);
    };
    out.mean_std_err = rel_se(0);
    out.m2_std_err = rel_se(1);
    if (var.empty()) {
        out.var_explicit = out.m2_explicit - out.mean_explicit * out.mean_explicit;
        out.var_jakob = out.m2_jakob - out.mean_jakob * out.mean_jakob;
    } else {
        for (const glm::dvec2& v : var) out.var_explicit += v.x / k, out.var_jakob += v.y / k;
    }
    out.var_rel_err = std::abs(out.var_jakob / out.var_explicit - 1.0);
    return out;
}

// Footprint of pixel (px, py) of a plane of pixels² square footprints tiling
// the uv square (the plane z = 0, normal +z: local = world).
Footprint pixel_footprint(int px, int py, int pixels) {
    const float side = 1.0f / static_cast<float>(pixels);
    Footprint fp;
    fp.uv =
        glm::vec2((static_cast<float>(px) + 0.5f) * side, (static_cast<float>(py) + 0.5f) * side);
    fp.duvdx = glm::vec2(side, 0.0f);
    fp.duvdy = glm::vec2(0.0f, side);
    return fp;
}

constexpr glm::dvec3 kCamera(0.5, -0.8, 1.2);

}  // namespace

ExplicitComparison compare_with_explicit_particles(int ndf, float alpha, double gamma_deg,
                                                   double log_density, int pixels, int realizations,
                                                   uint64_t seed) {
    ComparedModels models = compared_models(ndf, alpha, gamma_deg, log_density);
    const double gamma = gamma_deg * std::numbers::pi / 180.0;
    const glm::dvec3 light(0.5, 1.6, 0.9);
    std::vector<glm::dvec2> expl, jak;  // per realization: (mean, second moment) over pixels
    Pcg32 rng(seed, 0x65787031u);
    for (int r = 0; r < realizations; ++r) {
        models.field.seed = rng.next_uint();
        models.desc.seed = rng.next_uint();
        glm::dvec2 e(0.0), j(0.0);
        for (int py = 0; py < pixels; ++py)
            for (int px = 0; px < pixels; ++px) {
                const Footprint fp = pixel_footprint(px, py, pixels);
                const glm::dvec3 p(fp.uv.x, fp.uv.y, 0.0);
                const glm::vec3 wo(glm::normalize(kCamera - p)), wi(glm::normalize(light - p));
                const glm::vec3 h = glm::normalize(wi + wo);
                const double de = explicit_footprint_ndf(models.field, fp, wo, wi, float(gamma));
                const double dj = jakob2014_footprint_ndf(wo, wi, h, fp, models.desc);
                e += glm::dvec2(de, de * de);
                j += glm::dvec2(dj, dj * dj);
            }
        const double np = double(pixels) * pixels;
        expl.push_back(e / np);
        jak.push_back(j / np);
    }
    return summarize(expl, jak);
}

float smooth_test_environment(glm::vec3 d) {
    // Smooth at the scale of γ (no feature narrower than ~20°), so the cone
    // average jakob2014 applies to each particle's mirror direction changes
    // its radiance by O(γ²) only.
    return 1.0f + 0.8f * d.z + 0.6f * std::sin(3.0f * d.x) * std::cos(2.0f * d.y) +
           2.0f * std::exp(-8.0f * glm::dot(d - glm::vec3(0.3f, 0.5f, 0.81f),
                                            d - glm::vec3(0.3f, 0.5f, 0.81f)));
}

ExplicitComparison compare_with_explicit_environment(int ndf, float alpha, double gamma_deg,
                                                     double log_density, int pixels,
                                                     int realizations, int samples, uint64_t seed) {
    ComparedModels models = compared_models(ndf, alpha, gamma_deg, log_density);
    const std::function<glm::vec3(glm::vec3)> env = [](glm::vec3 d) {
        return glm::vec3(smooth_test_environment(d));
    };
    std::vector<glm::dvec2> expl, jak, var;
    Pcg32 rng(seed, 0x656e7631u);
    for (int r = 0; r < realizations; ++r) {
        models.field.seed = rng.next_uint();
        models.desc.seed = rng.next_uint();
        glm::dvec2 e(0.0), j(0.0);
        double j1 = 0.0, j2 = 0.0;  // sums of the first and second jakob2014 estimates
        for (int py = 0; py < pixels; ++py)
            for (int px = 0; px < pixels; ++px) {
                const Footprint fp = pixel_footprint(px, py, pixels);
                const glm::vec3 wo(glm::normalize(kCamera - glm::dvec3(fp.uv.x, fp.uv.y, 0.0)));
                const double le = explicit_environment_radiance(models.field, fp, wo, env).x;
                // jakob2014: two independent estimates X1, X2 of
                // ∫ L_env G2 D_P / (4 cos_o) dwi with its own sampling (002 §4);
                // E[X1 X2] = L², so the second moment carries no MC noise.
                double x[2] = {0.0, 0.0};
                for (double& xi : x) {
                    for (int k = 0; k < samples; ++k) {
                        const float uc = rng.next_float();
                        const float u1 = rng.next_float();
                        const glm::vec2 u(u1, rng.next_float());
                        const auto wi = jakob2014_sample_wi(models.desc, wo, uc, u);
                        if (!wi) continue;
                        const float pdf = jakob2014_pdf(models.desc, wo, *wi, true);
                        if (!(pdf > 0.0f)) continue;
                        const glm::vec3 h = glm::normalize(*wi + wo);
                        const double d = jakob2014_footprint_ndf(wo, *wi, h, fp, models.desc);
                        if (d == 0.0) continue;
                        const double g2 = shader::G2_SmithCorrelated(ndf, wo, *wi, alpha, alpha);
                        xi += env(*wi).x * g2 * d / (4.0 * wo.z * pdf);
                    }
                    xi /= samples;
                }
                e += glm::dvec2(le, le * le);
                j += glm::dvec2(0.5 * (x[0] + x[1]), x[0] * x[1]);
                j1 += x[0], j2 += x[1];
            }
        const double np = double(pixels) * pixels;
        expl.push_back(e / np);
        jak.push_back(j / np);
        // Per-pixel variance within the realization, unbiased for both: the
        // mean of L_p² minus the mean over pixel pairs p != q of L_p L_q
        // (jakob2014: X1_p X2_q, independent estimates, so MC noise adds no bias).
        const double pairs = np * (np - 1.0);
        var.push_back({e.y / np - (e.x * e.x - e.y) / pairs, j.y / np - (j1 * j2 - j.y) / pairs});
    }
    return summarize(expl, jak, var);
}

}  // namespace glintlab::jakob2014
