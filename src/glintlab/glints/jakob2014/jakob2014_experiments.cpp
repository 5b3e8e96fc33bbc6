#include "glintlab/glints/jakob2014/jakob2014_experiments.h"

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <numbers>

#include "glintlab/core/rng.h"
#include "glintlab/glints/jakob2014/jakob2014.h"
#include "glintlab/glints/registry.h"
#include "glintlab/microfacet/microfacet.h"
#include "glintlab/scene/scene.h"

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
        desc.model = "jakob2014";
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

ExplicitComparison compare_with_explicit_particles(int ndf, float alpha, double gamma_deg,
                                                   double log_density, int pixels, int realizations,
                                                   uint64_t seed) {
    NdfSpec spec;
    spec.ndf = ndf;
    spec.alpha_x = spec.alpha_y = alpha;
    const double gamma = gamma_deg * std::numbers::pi / 180.0;
    const int64_t n = std::llround(std::exp(log_density));
    const double side = 1.0 / pixels, area = side * side;
    // Scene: the uv square is the plane z = 0 (1 × 1); camera and light above it.
    const glm::dvec3 camera(0.5, -0.8, 1.2), light(0.5, 1.6, 0.9);
    auto dirs = [&](int px, int py, glm::dvec3& wi, glm::dvec3& wo) {
        const glm::dvec3 p((px + 0.5) * side, (py + 0.5) * side, 0.0);
        wo = glm::normalize(camera - p);
        wi = glm::normalize(light - p);
    };
    Model base;
    base.table = &ndf_integral_table(spec);
    base.particles = n;
    base.gamma = gamma;
    base.epsilon = 0.1;
    base.max_depth = 20;
    base.query_area = area;
    base.query_solid_angle = cone_solid_angle(gamma) / (4.0 * 0.8);
    double se = 0, se2 = 0, sj = 0, sj2 = 0;
    std::vector<double> ve, vj;  // per-realization moments, for the standard errors
    Pcg32 rng(seed, 0x65787031u);
    for (int r = 0; r < realizations; ++r) {
        // Explicit particles, bucketed by pixel.
        std::vector<std::vector<glm::dvec3>> cells(size_t(pixels) * size_t(pixels));
        const glm::vec3 up(0.0f, 0.0f, 1.0f);
        for (int64_t k = 0; k < n; ++k) {
            const double u = rng.next_double(), v = rng.next_double();
            const glm::vec3 m = shader::sample_vndf(ndf, up, alpha, alpha,
                                                    glm::vec2(rng.next_float(), rng.next_float()));
            const int cx = std::min(pixels - 1, int(u * pixels)),
                      cy = std::min(pixels - 1, int(v * pixels));
            cells[size_t(cy) * size_t(pixels) + size_t(cx)].push_back(glm::dvec3(m));
        }
        Model m = base;
        m.seed = rng.next_uint();
        double re = 0, re2 = 0, rj = 0, rj2 = 0;
        for (int py = 0; py < pixels; ++py)
            for (int px = 0; px < pixels; ++px) {
                glm::dvec3 wi, wo;
                dirs(px, py, wi, wo);
                const glm::dvec3 h = glm::normalize(wi + wo);
                const double scale = count_to_ndf(m, area, wi, h);
                const SphericalConic c = SphericalConic::make(wi, wo, gamma);
                int count = 0;
                for (const glm::dvec3& mm : cells[size_t(py) * size_t(pixels) + size_t(px)])
                    count += c.contains(mm);
                const double de = count * scale;
                UvParallelogram q;
                q.center = {(px + 0.5) * side, (py + 0.5) * side};
                q.e1 = {side, 0.0};
                q.e2 = {0.0, side};
                const double dj = query_count(m, q, wi, wo, nullptr).count * scale;
                re += de;
                re2 += de * de;
                rj += dj;
                rj2 += dj * dj;
            }
        const double np = double(pixels) * pixels;
        ve.push_back(re / np);
        ve.push_back(re2 / np);
        vj.push_back(rj / np);
        vj.push_back(rj2 / np);
        se += re / np;
        se2 += re2 / np;
        sj += rj / np;
        sj2 += rj2 / np;
    }
    ExplicitComparison out;
    out.mean_explicit = se / realizations;
    out.m2_explicit = se2 / realizations;
    out.mean_jakob = sj / realizations;
    out.m2_jakob = sj2 / realizations;
    out.mean_rel_err = std::abs(out.mean_jakob / out.mean_explicit - 1.0);
    out.m2_rel_err = std::abs(out.m2_jakob / out.m2_explicit - 1.0);
    // Standard errors from the spread of the per-realization moments.
    auto rel_se = [&](int which) {
        double a = 0, a2 = 0, b = 0, b2 = 0;
        for (int r = 0; r < realizations; ++r) {
            a += ve[size_t(2 * r + which)];
            a2 += ve[size_t(2 * r + which)] * ve[size_t(2 * r + which)];
            b += vj[size_t(2 * r + which)];
            b2 += vj[size_t(2 * r + which)] * vj[size_t(2 * r + which)];
        }
        const double k = realizations;
        const double va = std::max(0.0, a2 / k - (a / k) * (a / k)) / std::max(1.0, k - 1.0);
        const double vb = std::max(0.0, b2 / k - (b / k) * (b / k)) / std::max(1.0, k - 1.0);
        return std::sqrt(va + vb) / (a / k);
    };
    out.mean_std_err = rel_se(0);
    out.m2_std_err = rel_se(1);
    return out;
}

}  // namespace glintlab::jakob2014
