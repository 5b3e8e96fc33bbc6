// Counting and radiometry of the explicit ground truth (explicit.h).
#include "glintlab/glints/explicit/explicit.h"

#include <array>
#include <cmath>
#include <numbers>

#include "glintlab/glints/facet_extent.h"
#include "glintlab/microfacet/microfacet.h"

namespace glintlab {
namespace {

int ndf_id(NdfType t) {
    return t == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN;
}

// Mirror direction of wo about m (002 Eq. 7 with the roles of ωi and ωo
// exchanged, which the reflection law allows).
glm::vec3 mirror(glm::vec3 wo, glm::vec3 m) {
    return 2.0f * glm::dot(wo, m) * m - wo;
}

// n-point Gauss–Legendre nodes and weights on [-1, 1] (Newton on P_n).
template <int N>
struct GaussLegendre {
    std::array<double, N> x{}, w{};
    GaussLegendre() {
        for (int i = 0; i < N; ++i) {
            double z = std::cos(std::numbers::pi * (i + 0.75) / (N + 0.5));
            double dp = 1.0;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1.0, p1 = z;
                for (int k = 2; k <= N; ++k) {
                    const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                dp = N * (z * p1 - p0) / (z * z - 1.0);
                const double dz = p1 / dp;
                z -= dz;
                if (std::abs(dz) < 1e-15) break;
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        }
    }
};

}  // namespace

double explicit_cone_solid_angle(double gamma_rad) {
    // 2π(1 - cos γ): the reflected directions' cone, 4 times the half-vector
    // cone of facet_extent.h (dω_h = dω_i / 4 at normal incidence).
    return 4.0 * facet_cone_half_vector_solid_angle(gamma_rad);
}

uint64_t explicit_count(const ExplicitFacetField& field, const Footprint& fp, glm::vec3 wo,
                        glm::vec3 wi, float gamma_rad) {
    const float cos_gamma = std::cos(gamma_rad);
    uint64_t count = 0;
    for_each_explicit_facet(field, fp, [&](const ExplicitFacet& f) {
        if (glm::dot(wo, f.m) <= 0.0f) return;
        if (glm::dot(mirror(wo, f.m), wi) >= cos_gamma) ++count;
    });
    return count;
}

float explicit_footprint_ndf(const ExplicitFacetField& field, const Footprint& fp, glm::vec3 wo,
                             glm::vec3 wi, float gamma_rad) {
    const double area = explicit_footprint_area(fp);
    glm::vec3 h = wo + wi;
    if (!(area > 0.0) || glm::dot(h, h) == 0.0f) return 0.0f;
    h = glm::normalize(h);
    const double cos_ih = glm::dot(wi, h);
    if (h.z <= 0.0f || cos_ih <= 0.0) return 0.0f;
    // With a density map each facet counts by its area (ExplicitFacet::weight);
    // with a normal map by its area relative to a facet of the base surface,
    // (wo·n)(m·n) / ((wo·n_map)(m·n_map)) (explicit_facet_weight's ratio).
    double count = 0.0;
    if ((field.textures && field.textures->density) || field.has_macro_normals()) {
        const float cos_gamma = std::cos(gamma_rad);
        for_each_explicit_facet(field, fp, [&](const ExplicitFacet& f) {
            if (!(glm::dot(wo, f.m) > 0.0f && glm::dot(mirror(wo, f.m), wi) >= cos_gamma)) return;
            double c = f.weight;
            if (field.has_macro_normals()) {
                const double on = glm::dot(wo, f.n_map), mn = glm::dot(f.m, f.n_map);
                if (!(on > 0.0 && mn > 0.0)) return;
                c *= double(wo.z) * double(f.m.z) / (on * mn);
            }
            count += c;
        });
    } else {
        count = double(explicit_count(field, fp, wo, wi, gamma_rad));
    }
    const double n = double(explicit_facets_per_tile(field));
    // 002 Eq. 5-6 with the projected-area density's 1/(h·n) (explicit.h).
    return float(4.0 * cos_ih * count /
                 (n * area * explicit_cone_solid_angle(gamma_rad) * double(h.z)));
}

double explicit_direction_probability(const ExplicitFacetField& field, glm::vec3 wo, glm::vec3 wi,
                                      double gamma_rad) {
    // ∫_{cone(wi, γ)} D(h) (h·n) / (4 wo·h) dr,  h = normalize(wo + r): the
    // density of the mirror direction r of m ~ D(m)(m·n) (Jacobian
    // dm/dr = 1/(4 wo·h), Walter et al. 2007 Eq. 14). Gauss–Legendre in the
    // polar angle θ' ∈ [0, γ] (dω = sin θ' dθ' dφ), 2n-point GL in φ.
    static const GaussLegendre<48> gl_theta;
    static const GaussLegendre<96> gl_phi;
    const glm::dvec3 z = glm::normalize(glm::dvec3(wi));
    const glm::dvec3 a = std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 x = glm::normalize(glm::cross(a, z)), y = glm::cross(z, x);
    const glm::dvec3 o = glm::normalize(glm::dvec3(wo));
    double sum = 0.0;
    for (int i = 0; i < 48; ++i) {
        const double th = 0.5 * gamma_rad * (gl_theta.x[i] + 1.0);
        const double wth = 0.5 * gamma_rad * gl_theta.w[i] * std::sin(th);
        for (int j = 0; j < 96; ++j) {
            const double ph = std::numbers::pi * (gl_phi.x[j] + 1.0);
            const double wph = std::numbers::pi * gl_phi.w[j];
            const glm::dvec3 r =
                std::cos(th) * z + std::sin(th) * (std::cos(ph) * x + std::sin(ph) * y);
            const glm::dvec3 hs = o + r;
            const double len = glm::length(hs);
            if (len == 0.0) continue;
            const glm::dvec3 h = hs / len;
            const double cos_oh = glm::dot(o, h);
            if (h.z <= 0.0 || cos_oh <= 0.0) continue;
            const double d =
                shader::D_Microfacet(ndf_id(field.ndf), glm::vec3(h), field.alpha_x, field.alpha_y);
            sum += wth * wph * d * h.z / (4.0 * cos_oh);
        }
    }
    return sum;
}

float explicit_facet_weight(const ExplicitFacetField& field, glm::vec3 wo, const ExplicitFacet& f,
                            glm::vec3& r) {
    if (!field.has_macro_normals()) return explicit_facet_weight(field, wo, f.m, r);
    const glm::vec3 t = f.t_map, b = glm::cross(f.n_map, t);
    auto to_map = [&](glm::vec3 v) {
        return glm::vec3(glm::dot(v, t), glm::dot(v, b), glm::dot(v, f.n_map));
    };
    glm::vec3 r_map;
    const float w = explicit_facet_weight(field, to_map(wo), to_map(f.m), r_map);
    r = r_map.x * t + r_map.y * b + r_map.z * f.n_map;
    return w;
}

float explicit_facet_weight(const ExplicitFacetField& field, glm::vec3 wo, glm::vec3 m,
                            glm::vec3& r) {
    const float cos_om = glm::dot(wo, m);
    r = mirror(wo, m);
    if (cos_om <= 0.0f || wo.z <= 0.0f || m.z <= 0.0f || r.z <= 0.0f) return 0.0f;
    const float g2 =
        shader::G2_SmithCorrelated(ndf_id(field.ndf), wo, r, field.alpha_x, field.alpha_y);
    return cos_om * g2 / (wo.z * m.z);
}

glm::vec3 explicit_environment_radiance(const ExplicitFacetField& field, const Footprint& fp,
                                        glm::vec3 wo,
                                        const std::function<glm::vec3(glm::vec3)>& env,
                                        const std::function<glm::vec3(float)>& fresnel) {
    const double area = explicit_footprint_area(fp);
    if (!(area > 0.0) || wo.z <= 0.0f) return glm::vec3(0.0f);
    glm::dvec3 sum(0.0);
    for_each_explicit_facet(field, fp, [&](const ExplicitFacet& f) {
        glm::vec3 r;
        const float w = explicit_facet_weight(field, wo, f, r);
        if (w <= 0.0f) return;
        glm::vec3 L = env(r);
        if (fresnel) L *= fresnel(glm::dot(wo, f.m));
        sum += glm::dvec3(w * f.weight * L);
    });
    // 003 Eq. 5: normalised by the expected count E[N_P] = N a(A).
    const double n = double(explicit_facets_per_tile(field));
    return glm::vec3(sum / (n * area));
}

glm::vec3 explicit_environment_radiance(const ExplicitFacetField& field, const Footprint& fp,
                                        glm::vec3 wo,
                                        const std::function<glm::vec3(glm::vec3)>& env) {
    return explicit_environment_radiance(field, fp, wo, env, nullptr);
}

}  // namespace glintlab
