#include "glintlab/microfacet/bxdfs.h"

#include <cmath>

#include "glintlab/microfacet/microfacet.h"

// The BRDF values, shared with the GPU forward pass (glints/material.glsl).
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/microfacet/bxdfs.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

namespace sh = glintlab::shader;

int ndf_id(NdfType t) {
    return t == NdfType::Beckmann ? sh::NDF_BECKMANN : sh::NDF_GGX;
}

bool same_hemisphere(glm::vec3 a, glm::vec3 b) {
    return a.z * b.z > 0.0f;
}
float abs_cos(glm::vec3 w) {
    return std::abs(w.z);
}
glm::vec3 reflect_about(glm::vec3 wo, glm::vec3 n) {
    return -wo + 2.0f * glm::dot(wo, n) * n;
}
glm::vec3 face_up(glm::vec3 n) {
    return n.z < 0.0f ? -n : n;
}

// Snell refraction of wo about n (pbrt-v4 Refract): eta is the relative IOR for
// wo on n's side; when wo is on the other side the roles swap. Returns false on
// total internal reflection. etap receives the IOR ratio actually used.
bool refract_dir(glm::vec3 wo, glm::vec3 n, float eta, float& etap, glm::vec3& wt) {
    float cos_o = glm::dot(n, wo);
    if (cos_o < 0.0f) {
        eta = 1.0f / eta;
        cos_o = -cos_o;
        n = -n;
    }
    const float sin2_o = std::max(0.0f, 1.0f - cos_o * cos_o);
    const float sin2_t = sin2_o / (eta * eta);
    if (sin2_t >= 1.0f) return false;
    const float cos_t = std::sqrt(1.0f - sin2_t);
    wt = -wo / eta + (cos_o / eta - cos_t) * n;
    etap = eta;
    return true;
}

// Cosine-weighted hemisphere direction (Malley's method on a concentric disk,
// Shirley & Chiu 1997), z >= 0.
glm::vec3 sample_cosine_hemisphere(glm::vec2 u) {
    const float a = 2.0f * u.x - 1.0f;
    const float b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f, 1.0f};
    float r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (sh::PI / 4.0f) * (b / a);
    } else {
        r = b;
        phi = sh::PI / 2.0f - (sh::PI / 4.0f) * (a / b);
    }
    const float x = r * std::cos(phi);
    const float y = r * std::sin(phi);
    return {x, y, std::sqrt(std::max(0.0f, 1.0f - x * x - y * y))};
}

}  // namespace

// --- MicrofacetDistribution ---------------------------------------------------
float MicrofacetDistribution::D(glm::vec3 wm) const {
    return sh::D_Microfacet(ndf_id(ndf), wm, alpha_x, alpha_y);
}
float MicrofacetDistribution::Lambda(glm::vec3 w) const {
    return sh::Lambda_Microfacet(ndf_id(ndf), w, alpha_x, alpha_y);
}
float MicrofacetDistribution::G1(glm::vec3 w) const {
    return sh::G1_Smith(ndf_id(ndf), w, alpha_x, alpha_y);
}
float MicrofacetDistribution::G2(glm::vec3 wo, glm::vec3 wi) const {
    return sh::G2_SmithCorrelated(ndf_id(ndf), wo, wi, alpha_x, alpha_y);
}
glm::vec3 MicrofacetDistribution::sample_wm(glm::vec3 wo, glm::vec2 u) const {
    return sh::sample_vndf(ndf_id(ndf), face_up(wo), alpha_x, alpha_y, u);
}
float MicrofacetDistribution::pdf(glm::vec3 wo, glm::vec3 wm) const {
    // Observers below the surface (dielectric interiors) see the same
    // microsurface from the other side: Lambda is even in w.z, so the visible
    // density of the flipped observer is the density of sample_wm(wo).
    const glm::vec3 w = face_up(wo);
    const float wdotm = std::max(0.0f, glm::dot(w, wm));
    if (w.z <= 0.0f) return 0.0f;
    return G1(w) * wdotm * D(wm) / w.z;
}

// --- Diffuse ------------------------------------------------------------------
glm::vec3 DiffuseBxdf::f(glm::vec3 wo, glm::vec3 wi) const {
    if (!same_hemisphere(wo, wi)) return glm::vec3(0.0f);
    return sh::diffuse_f(albedo);
}
float DiffuseBxdf::pdf(glm::vec3 wo, glm::vec3 wi) const {
    if (!same_hemisphere(wo, wi)) return 0.0f;
    return abs_cos(wi) * sh::INV_PI;
}
std::optional<BsdfSample> DiffuseBxdf::sample(glm::vec3 wo, float /*uc*/, glm::vec2 u) const {
    if (wo.z == 0.0f) return std::nullopt;
    glm::vec3 wi = sample_cosine_hemisphere(u);
    if (wo.z < 0.0f) wi.z = -wi.z;
    if (wi.z == 0.0f) return std::nullopt;
    return BsdfSample{f(wo, wi), wi, pdf(wo, wi), false, false};
}

// --- Conductor ----------------------------------------------------------------
glm::vec3 ConductorBxdf::f(glm::vec3 wo, glm::vec3 wi) const {
    if (!same_hemisphere(wo, wi) || dist.effectively_smooth()) return glm::vec3(0.0f);
    return sh::conductor_f(ndf_id(dist.ndf), dist.alpha_x, dist.alpha_y, eta, k, wo, wi);
}
float ConductorBxdf::pdf(glm::vec3 wo, glm::vec3 wi) const {
    if (!same_hemisphere(wo, wi) || dist.effectively_smooth()) return 0.0f;
    glm::vec3 wm = wo + wi;
    if (glm::dot(wm, wm) == 0.0f) return 0.0f;
    wm = face_up(glm::normalize(wm));
    // Reflection Jacobian d wm / d wi = 1 / (4 |wo.wm|) (Walter et al. 2007 Eq. 14).
    return dist.pdf(wo, wm) / (4.0f * std::abs(glm::dot(wo, wm)));
}
std::optional<BsdfSample> ConductorBxdf::sample(glm::vec3 wo, float /*uc*/, glm::vec2 u) const {
    if (wo.z == 0.0f) return std::nullopt;
    if (dist.effectively_smooth()) {
        const glm::vec3 wi(-wo.x, -wo.y, wo.z);
        const glm::vec3 F = sh::F_Conductor(abs_cos(wi), eta, k) / abs_cos(wi);
        return BsdfSample{F, wi, 1.0f, true, false};
    }
    const glm::vec3 wm = dist.sample_wm(wo, u);
    const glm::vec3 wi = reflect_about(wo, wm);
    if (!same_hemisphere(wo, wi)) return std::nullopt;
    const float p = pdf(wo, wi);
    if (p == 0.0f) return std::nullopt;
    return BsdfSample{f(wo, wi), wi, p, false, false};
}

// --- Dielectric ---------------------------------------------------------------
namespace {
// Generalised half vector (Walter et al. 2007 Eq. 16), facing +z, or nullopt
// when the configuration is degenerate or a microfacet would be back-facing.
struct HalfVector {
    glm::vec3 wm;
    float etap;
    bool reflect;
};
std::optional<HalfVector> dielectric_half_vector(glm::vec3 wo, glm::vec3 wi, float eta) {
    const float cos_o = wo.z, cos_i = wi.z;
    if (cos_o == 0.0f || cos_i == 0.0f) return std::nullopt;
    const bool reflect = cos_o * cos_i > 0.0f;
    const float etap = reflect ? 1.0f : (cos_o > 0.0f ? eta : 1.0f / eta);
    glm::vec3 wm = wi * etap + wo;
    if (glm::dot(wm, wm) == 0.0f) return std::nullopt;
    wm = face_up(glm::normalize(wm));
    // Both directions must see the microfacet from the side they lie on.
    if (glm::dot(wm, wi) * cos_i < 0.0f || glm::dot(wm, wo) * cos_o < 0.0f) return std::nullopt;
    return HalfVector{wm, etap, reflect};
}
}  // namespace

glm::vec3 DielectricBxdf::f(glm::vec3 wo, glm::vec3 wi) const {
    if (is_specular()) return glm::vec3(0.0f);
    const auto h = dielectric_half_vector(wo, wi, eta);
    if (!h) return glm::vec3(0.0f);
    if (h->reflect)
        return glm::vec3(sh::dielectric_reflection_f(ndf_id(dist.ndf), dist.alpha_x, dist.alpha_y,
                                                     eta, wo, wi, h->wm));
    const float cos_o = wo.z, cos_i = wi.z;
    const float F = sh::F_Dielectric(glm::dot(wo, h->wm), eta);
    const float DG = dist.D(h->wm) * dist.G2(wo, wi);
    // Walter et al. 2007 Eq. 21 with the generalised half vector; the 1/eta'^2
    // converts importance to radiance (Veach 1997 §5.2, pbrt-v4 radiance mode).
    const float idm = glm::dot(wi, h->wm), odm = glm::dot(wo, h->wm);
    const float denom = (idm + odm / h->etap) * (idm + odm / h->etap) * cos_i * cos_o;
    const float ft = DG * (1.0f - F) * std::abs(idm * odm / denom);
    return glm::vec3(ft / (h->etap * h->etap));
}

float DielectricBxdf::pdf(glm::vec3 wo, glm::vec3 wi) const {
    if (is_specular()) return 0.0f;
    const auto h = dielectric_half_vector(wo, wi, eta);
    if (!h) return 0.0f;
    const float R = sh::F_Dielectric(glm::dot(wo, h->wm), eta);
    const float T = 1.0f - R;
    if (h->reflect) return dist.pdf(wo, h->wm) / (4.0f * std::abs(glm::dot(wo, h->wm))) * R;
    const float idm = glm::dot(wi, h->wm), odm = glm::dot(wo, h->wm);
    const float s = idm + odm / h->etap;
    // Refraction Jacobian d wm / d wi = |wi.wm| / (wi.wm + wo.wm / eta')^2
    // (Walter et al. 2007 Eq. 17, written for wm normalised from wi eta' + wo).
    return dist.pdf(wo, h->wm) * std::abs(idm) / (s * s) * T;
}

std::optional<BsdfSample> DielectricBxdf::sample(glm::vec3 wo, float uc, glm::vec2 u) const {
    if (wo.z == 0.0f) return std::nullopt;
    if (is_specular()) {
        // Smooth interface: choose reflection with probability F.
        const float R = sh::F_Dielectric(wo.z, eta), T = 1.0f - R;
        if (uc < R) {
            const glm::vec3 wi(-wo.x, -wo.y, wo.z);
            return BsdfSample{glm::vec3(R / abs_cos(wi)), wi, R, true, false};
        }
        glm::vec3 wi;
        float etap;
        if (!refract_dir(wo, glm::vec3(0, 0, 1), eta, etap, wi) || wi.z == 0.0f)
            return std::nullopt;
        const float ft = T / abs_cos(wi) / (etap * etap);
        return BsdfSample{glm::vec3(ft), wi, T, true, true};
    }
    const glm::vec3 wm = dist.sample_wm(wo, u);
    const float R = sh::F_Dielectric(glm::dot(wo, wm), eta);
    glm::vec3 wi;
    bool transmission = false;
    if (uc < R) {
        wi = reflect_about(wo, wm);
        if (!same_hemisphere(wo, wi)) return std::nullopt;
    } else {
        float etap;
        if (!refract_dir(wo, wm, eta, etap, wi)) return std::nullopt;
        if (same_hemisphere(wo, wi) || wi.z == 0.0f) return std::nullopt;
        transmission = true;
    }
    // f and pdf are recomputed from (wo, wi) so that they match f() and pdf()
    // exactly; the half vector reconstructed from wi is wm up to rounding.
    const float p = pdf(wo, wi);
    if (p == 0.0f) return std::nullopt;
    return BsdfSample{f(wo, wi), wi, p, false, transmission};
}

// --- Plastic ------------------------------------------------------------------
float PlasticBxdf::specular_probability(glm::vec3 wo) const {
    const float Fo = sh::F_Dielectric(abs_cos(wo), eta);
    const float kd = std::max(diffuse.x, std::max(diffuse.y, diffuse.z));
    const float ws = Fo, wd = (1.0f - Fo) * kd;
    return ws + wd > 0.0f ? ws / (ws + wd) : 1.0f;
}

glm::vec3 PlasticBxdf::f(glm::vec3 wo, glm::vec3 wi) const {
    if (!same_hemisphere(wo, wi)) return glm::vec3(0.0f);
    return sh::plastic_f(diffuse, eta, ndf_id(dist.ndf), dist.alpha_x, dist.alpha_y, wo, wi);
}

float PlasticBxdf::pdf(glm::vec3 wo, glm::vec3 wi) const {
    if (!same_hemisphere(wo, wi)) return 0.0f;
    const float ps = specular_probability(wo);
    float p = (1.0f - ps) * abs_cos(wi) * sh::INV_PI;
    if (!dist.effectively_smooth()) {
        const glm::vec3 wm = face_up(glm::normalize(wo + wi));
        p += ps * dist.pdf(wo, wm) / (4.0f * std::abs(glm::dot(wo, wm)));
    }
    return p;
}

std::optional<BsdfSample> PlasticBxdf::sample(glm::vec3 wo, float uc, glm::vec2 u) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float ps = specular_probability(wo);
    glm::vec3 wi;
    if (uc < ps) {
        if (dist.effectively_smooth()) {
            wi = glm::vec3(-wo.x, -wo.y, wo.z);
            const float F = sh::F_Dielectric(abs_cos(wo), eta);
            return BsdfSample{glm::vec3(F / abs_cos(wi)), wi, ps, true, false};
        }
        wi = reflect_about(wo, dist.sample_wm(wo, u));
    } else {
        wi = sample_cosine_hemisphere(u);
        if (wo.z < 0.0f) wi.z = -wi.z;
    }
    if (!same_hemisphere(wo, wi)) return std::nullopt;
    const float p = pdf(wo, wi);
    if (p == 0.0f) return std::nullopt;
    return BsdfSample{f(wo, wi), wi, p, false, false};
}

// --- Metallic-roughness (glTF) --------------------------------------------------
PlasticBxdf MetallicRoughnessBxdf::dielectric() const {
    PlasticBxdf p;
    p.diffuse = base_color;
    p.dist = dist;
    p.eta = eta;
    return p;
}

glm::vec3 MetallicRoughnessBxdf::f(glm::vec3 wo, glm::vec3 wi) const {
    if (!same_hemisphere(wo, wi)) return glm::vec3(0.0f);
    return sh::metallic_roughness_f(base_color, metallic, eta, ndf_id(dist.ndf), dist.alpha_x,
                                    dist.alpha_y, wo, wi);
}

float MetallicRoughnessBxdf::pdf(glm::vec3 wo, glm::vec3 wi) const {
    if (!same_hemisphere(wo, wi)) return 0.0f;
    float p = metallic < 1.0f ? (1.0f - metallic) * dielectric().pdf(wo, wi) : 0.0f;
    if (metallic > 0.0f && !dist.effectively_smooth()) {
        glm::vec3 wm = wo + wi;
        if (glm::dot(wm, wm) == 0.0f) return p;
        wm = face_up(glm::normalize(wm));
        p += metallic * dist.pdf(wo, wm) / (4.0f * std::abs(glm::dot(wo, wm)));
    }
    return p;
}

std::optional<BsdfSample> MetallicRoughnessBxdf::sample(glm::vec3 wo, float uc, glm::vec2 u) const {
    if (wo.z == 0.0f) return std::nullopt;
    const PlasticBxdf plastic = dielectric();
    if (dist.effectively_smooth()) {
        // Both specular lobes are the mirror direction's delta: chosen with
        // the metal's probability plus the dielectric's share of its own.
        const float ps = (1.0f - metallic) * plastic.specular_probability(wo);
        const float p_delta = metallic + ps;
        if (uc < p_delta) {
            const glm::vec3 wi(-wo.x, -wo.y, wo.z);
            const float c = abs_cos(wi);
            const glm::vec3 F = metallic * sh::F_Schlick(base_color, c) +
                                (1.0f - metallic) * sh::F_Dielectric(c, eta);
            return BsdfSample{F / c, wi, p_delta, true, false};
        }
        glm::vec3 wi = sample_cosine_hemisphere(u);
        if (wo.z < 0.0f) wi.z = -wi.z;
        if (wi.z == 0.0f) return std::nullopt;
        // The diffuse lobe's share of the (non-delta) pdf.
        return BsdfSample{f(wo, wi), wi, pdf(wo, wi), false, false};
    }
    glm::vec3 wi;
    if (uc < metallic) {
        wi = reflect_about(wo, dist.sample_wm(wo, u));
    } else {
        const float uc_plastic = metallic < 1.0f ? (uc - metallic) / (1.0f - metallic) : 0.0f;
        const auto s = plastic.sample(wo, std::min(uc_plastic, 0x1.fffffep-1f), u);
        if (!s) return std::nullopt;
        wi = s->wi;
    }
    if (!same_hemisphere(wo, wi)) return std::nullopt;
    const float p = pdf(wo, wi);
    if (p == 0.0f) return std::nullopt;
    return BsdfSample{f(wo, wi), wi, p, false, false};
}

// --- Variant dispatch -----------------------------------------------------------
glm::vec3 bxdf_f(const Bxdf& bxdf, glm::vec3 wo, glm::vec3 wi) {
    return std::visit([&](const auto& b) { return b.f(wo, wi); }, bxdf);
}
float bxdf_pdf(const Bxdf& bxdf, glm::vec3 wo, glm::vec3 wi) {
    return std::visit([&](const auto& b) { return b.pdf(wo, wi); }, bxdf);
}
std::optional<BsdfSample> bxdf_sample(const Bxdf& bxdf, glm::vec3 wo, float uc, glm::vec2 u) {
    return std::visit([&](const auto& b) { return b.sample(wo, uc, u); }, bxdf);
}
bool bxdf_is_specular(const Bxdf& bxdf) {
    return std::visit([](const auto& b) { return b.is_specular(); }, bxdf);
}

}  // namespace glintlab
