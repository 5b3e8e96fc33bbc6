#include "glintlab/glints/jakob2014/jakob2014.h"

#include <bit>
#include <cmath>
#include <numbers>
#include <variant>

#include "glintlab/core/error.h"
#include "glintlab/core/hash.h"
#include "glintlab/core/radical_inverse.h"
#include "glintlab/glints/glint_desc.h"
#include "glintlab/microfacet/microfacet.h"

namespace glintlab {
namespace jakob2014 {
namespace {

// E[ωi·h] of the Eq. 11 statistic E[σ(Ω_h)] = σ(Ω_o) / (4 E[ωi·h]): a
// typical 75° between light and view (MODELS.md).
constexpr double kTypicalCosThetaD = 0.8;

float smooth_d(const GlintDesc& desc, glm::vec3 h) {
    return shader::D_Microfacet_correlated(
        desc.ndf == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN, h, desc.alpha_x,
        desc.alpha_y, desc.slope_correlation);
}

uint32_t sobol2(uint32_t i) {
    uint32_t r = 0u;
    for (uint32_t v = 1u << 31u; i; i >>= 1u, v ^= v >> 1u)
        if (i & 1u) r ^= v;
    return r;
}

// Orthonormal basis around unit w.
void basis(glm::dvec3 w, glm::dvec3& t, glm::dvec3& b) {
    const glm::dvec3 a = std::abs(w.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    t = glm::normalize(glm::cross(w, a));
    b = glm::cross(w, t);
}

}  // namespace

// α on the grid 2^(k/64) (steps of 1.1 %): each α has its own NDF integral
// table (built on first use, kept), so a roughness resolved per hit would
// build one per pixel without bound; on the grid a scene needs at most
// ~640 per axis, and the lobe moves by less than its own Monte Carlo noise.
float snapped_alpha(float alpha) {
    return std::exp2(std::round(std::log2(alpha) * 64.0f) / 64.0f);
}

// ρ on the grid atanh(ρ) = k/64 (1 − |ρ| in steps of 3 % near ±0.99), for
// the same reason.
float snapped_rho(float rho) {
    return std::tanh(std::round(std::atanh(rho) * 64.0f) / 64.0f);
}

NdfSpec ndf_spec(const GlintDesc& desc) {
    NdfSpec s;
    s.ndf = desc.ndf == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN;
    s.alpha_x = desc.alpha_varies ? snapped_alpha(desc.alpha_x) : desc.alpha_x;
    s.alpha_y = desc.alpha_varies ? snapped_alpha(desc.alpha_y) : desc.alpha_y;
    s.rho = desc.slope_correlation != 0.0f ? snapped_rho(desc.slope_correlation) : 0.0f;
    return s;
}

double cone_solid_angle(double gamma) {
    return 2.0 * std::numbers::pi * (1.0 - std::cos(gamma));
}

Model make_model(const GlintDesc& desc) {
    const Jakob2014Params& p = std::get<Jakob2014Params>(desc.params);
    Model m;
    m.table = &ndf_integral_table(ndf_spec(desc));
    m.particles = std::llround(std::exp(double(desc.log_density)));
    m.gamma = double(p.gamma_deg) * std::numbers::pi / 180.0;
    m.epsilon = p.error_threshold;
    m.max_depth = p.max_depth;
    m.seed = desc.seed;
    m.chromatic = p.chromatic;
    m.query_area = p.query_area;
    m.query_solid_angle = cone_solid_angle(m.gamma) / (4.0 * kTypicalCosThetaD);
    return m;
}

double count_to_ndf(const Model& m, double footprint_area, glm::dvec3 wi, glm::dvec3 h) {
    const double denom = double(m.particles) * footprint_area * cone_solid_angle(m.gamma) * h.z;
    if (!(denom > 0.0)) return 0.0;
    return 4.0 * std::max(0.0, glm::dot(wi, h)) / denom;
}

QueryStats& thread_stats() {
    thread_local QueryStats s;
    return s;
}

glm::dvec2 qmc_point(int i) {
    const uint32_t u = uint32_t(i);
    return {reverse_bits(u) * 0x1p-32 + 1.0 / 128.0, sobol2(u) * 0x1p-32 + 1.0 / 128.0};
}

}  // namespace jakob2014

namespace {

constexpr int kQmcPoints = 64;  // 002 §4: "64 samples of a (0,2) rule"

// D_P per channel, or nullopt where the smooth D applies (degenerate footprint).
std::optional<glm::dvec3> query_ndf(glm::vec3 wo, glm::vec3 wi, glm::vec3 h, const Footprint& fp,
                                    const GlintDesc& desc) {
    using namespace jakob2014;
    UvParallelogram q;
    q.center = glm::dvec2(fp.uv);
    q.e1 = glm::dvec2(fp.duvdx);
    q.e2 = glm::dvec2(fp.duvdy);
    const double a = q.area();
    if (!(a > 1e-30) || !std::isfinite(a) || !std::isfinite(q.center.x) ||
        !std::isfinite(q.center.y))
        return std::nullopt;
    const Model m = make_model(desc);
    const QueryResult r = query_count(m, q, glm::dvec3(wi), glm::dvec3(wo), &thread_stats());
    const double s = count_to_ndf(m, a, glm::dvec3(wi), glm::dvec3(h));
    return r.area * s;
}

}  // namespace

float jakob2014_footprint_ndf(glm::vec3 wo, glm::vec3 wi, glm::vec3 h, const Footprint& footprint,
                              const GlintDesc& desc) {
    const auto d = query_ndf(wo, wi, h, footprint, desc);
    if (!d) return jakob2014::smooth_d(desc, h);
    return float(std::get<Jakob2014Params>(desc.params).chromatic ? (d->x + d->y + d->z) / 3.0
                                                                  : d->x);
}

glm::vec3 jakob2014_footprint_ndf_rgb(glm::vec3 wo, glm::vec3 wi, glm::vec3 h,
                                      const Footprint& footprint, const GlintDesc& desc) {
    const auto d = query_ndf(wo, wi, h, footprint, desc);
    if (!d) return glm::vec3(jakob2014::smooth_d(desc, h));
    return glm::vec3(*d);
}

std::optional<glm::vec3> jakob2014_sample_wi(const GlintDesc& desc, glm::vec3 wo, float uc,
                                             glm::vec2 u) {
    if (wo.z <= 0.0f) return std::nullopt;
    const int ndf = desc.ndf == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN;
    const glm::vec3 m = shader::sample_vndf(ndf, wo, 2.0f * desc.alpha_x, 2.0f * desc.alpha_y, u);
    const glm::dvec3 w1 = glm::normalize(glm::dvec3(glm::reflect(-wo, m)));
    // Uniform direction in the cone of radius γ around w1. GlintBxdf::sample
    // provides three uniforms; the cone's azimuth is a hash of all three
    // (a deterministic decorrelated fourth number).
    const double gamma =
        std::get<Jakob2014Params>(desc.params).gamma_deg * std::numbers::pi / 180.0;
    const uint32_t hbits =
        shader::pcg_hash(std::bit_cast<uint32_t>(uc) ^
                         shader::pcg_hash(std::bit_cast<uint32_t>(u.x) ^
                                          shader::pcg_hash(std::bit_cast<uint32_t>(u.y))));
    const double u4 = hbits * 0x1p-32;
    const double ct = 1.0 - double(uc) * (1.0 - std::cos(gamma));
    const double st = std::sqrt(std::max(0.0, 1.0 - ct * ct));
    const double phi = 2.0 * std::numbers::pi * u4;
    glm::dvec3 t, b;
    jakob2014::basis(w1, t, b);
    const glm::dvec3 wi = ct * w1 + st * (std::cos(phi) * t + std::sin(phi) * b);
    if (wi.z <= 0.0) return std::nullopt;
    return glm::vec3(glm::normalize(wi));
}

float jakob2014_pdf(const GlintDesc& desc, glm::vec3 wo, glm::vec3 wi, bool full_sphere) {
    if (wo.z <= 0.0f || (!full_sphere && wi.z <= 0.0f)) return 0.0f;
    const int ndf = desc.ndf == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN;
    const float ax = 2.0f * desc.alpha_x, ay = 2.0f * desc.alpha_y;
    const double gamma =
        std::get<Jakob2014Params>(desc.params).gamma_deg * std::numbers::pi / 180.0;
    // Density of w1 = reflect(-wo, m), m ~ visible normals at 2α, on the whole
    // sphere: D(m) G1(wo) (wo·m)/wo.z / (4 wo·m) = D(m) G1(wo) / (4 wo.z).
    const double g1 = shader::G1_Smith(ndf, wo, ax, ay);
    const glm::dvec3 w0(wo), wd = glm::normalize(glm::dvec3(wi));
    glm::dvec3 t, b;
    jakob2014::basis(wd, t, b);
    const double one_minus_cos = 1.0 - std::cos(gamma);
    // The net's azimuths are fixed: (cos φ, sin φ) tabulated once.
    struct Net {
        double x[kQmcPoints], c[kQmcPoints], s[kQmcPoints];
        Net() {
            for (int i = 0; i < kQmcPoints; ++i) {
                const glm::dvec2 p = jakob2014::qmc_point(i);
                x[i] = p.x;
                c[i] = std::cos(2.0 * std::numbers::pi * p.y);
                s[i] = std::sin(2.0 * std::numbers::pi * p.y);
            }
        }
    };
    static const Net net;
    double sum = 0.0;
    for (int i = 0; i < kQmcPoints; ++i) {
        const double ct = 1.0 - net.x[i] * one_minus_cos;
        const double st = std::sqrt(std::max(0.0, 1.0 - ct * ct));
        const glm::dvec3 w1 = ct * wd + st * (net.c[i] * t + net.s[i] * b);
        const glm::dvec3 hs = w0 + w1;
        const double len2 = glm::dot(hs, hs);
        if (len2 <= 0.0) continue;
        const glm::dvec3 m = hs / std::sqrt(len2);
        if (m.z <= 0.0 || glm::dot(w0, m) <= 0.0) continue;
        sum += double(shader::D_Microfacet(ndf, glm::vec3(m), ax, ay));
    }
    sum *= g1 / (4.0 * double(wo.z));
    return float(sum / kQmcPoints);
}

}  // namespace glintlab
