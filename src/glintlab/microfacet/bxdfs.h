// CPU BxDFs of the smooth (non-glinty) microfacet model: the reference every
// glint model converges to. Directions are in the local shading frame
// (z = normal); wo and wi both point away from the surface. Conventions follow
// pbrt-v4: f() has no cosine factor; pdf() is a solid-angle density that omits
// delta lobes; a delta sample carries f = F / |cos wi| and the discrete
// probability of its lobe in pdf.
#pragma once

#include <algorithm>
#include <glm/glm.hpp>
#include <optional>
#include <variant>

namespace glintlab {

enum class NdfType { Beckmann, GGX };

// Roughness below which a lobe is treated as a perfect mirror / refractor
// (pbrt-v4 TrowbridgeReitzDistribution::EffectivelySmooth uses the same 1e-3;
// the shared BRDF values, bxdfs.glsl microfacet_effectively_smooth, too).
inline constexpr float kSmoothAlpha = 1e-3f;

// Anisotropic microfacet distribution with Smith (height-correlated) masking;
// thin wrapper over the shared shading functions in microfacet.h.
struct MicrofacetDistribution {
    NdfType ndf = NdfType::GGX;
    float alpha_x = 0.5f;
    float alpha_y = 0.5f;

    bool effectively_smooth() const { return std::max(alpha_x, alpha_y) < kSmoothAlpha; }
    float D(glm::vec3 wm) const;
    float Lambda(glm::vec3 w) const;
    float G1(glm::vec3 w) const;                 // Smith, without H(w.m)
    float G2(glm::vec3 wo, glm::vec3 wi) const;  // height-correlated Smith
    // Visible normal for an observer wo (either hemisphere: wo is flipped up).
    glm::vec3 sample_wm(glm::vec3 wo, glm::vec2 u) const;
    // Density of sample_wm(wo) at wm: G1(wo) max(0, w.wm) D(wm) / w.z, w = wo flipped up.
    float pdf(glm::vec3 wo, glm::vec3 wm) const;
};

struct BsdfSample {
    glm::vec3 f{0.0f};  // BSDF value (no cosine)
    glm::vec3 wi{0.0f};
    float pdf = 0.0f;  // solid-angle pdf, or the lobe's discrete probability when is_delta
    bool is_delta = false;
    bool is_transmission = false;
};

// Lambertian reflection, cosine-weighted sampling.
struct DiffuseBxdf {
    glm::vec3 albedo{0.5f};

    glm::vec3 f(glm::vec3 wo, glm::vec3 wi) const;
    float pdf(glm::vec3 wo, glm::vec3 wi) const;
    std::optional<BsdfSample> sample(glm::vec3 wo, float uc, glm::vec2 u) const;
    bool is_specular() const { return false; }
};

// Cook-Torrance metal: D G2 F / (4 cos_o cos_i), complex-IOR Fresnel,
// visible-normal sampling; a mirror when the distribution is effectively smooth.
struct ConductorBxdf {
    MicrofacetDistribution dist;
    glm::vec3 eta{0.2f};
    glm::vec3 k{3.0f};

    glm::vec3 f(glm::vec3 wo, glm::vec3 wi) const;
    float pdf(glm::vec3 wo, glm::vec3 wi) const;
    std::optional<BsdfSample> sample(glm::vec3 wo, float uc, glm::vec2 u) const;
    bool is_specular() const { return dist.effectively_smooth(); }
};

// Rough dielectric interface, reflection and refraction (Walter et al. 2007,
// generalised half vector; pbrt-v4 DielectricBxDF), radiance transport: the
// transmitted radiance is divided by eta'^2. eta = IOR inside / outside, where
// inside is the -z side.
struct DielectricBxdf {
    MicrofacetDistribution dist;
    float eta = 1.5f;

    glm::vec3 f(glm::vec3 wo, glm::vec3 wi) const;
    float pdf(glm::vec3 wo, glm::vec3 wi) const;
    std::optional<BsdfSample> sample(glm::vec3 wo, float uc, glm::vec2 u) const;
    bool is_specular() const { return eta == 1.0f || dist.effectively_smooth(); }
};

// Plastic: dielectric-Fresnel microfacet specular reflection over a Lambertian
// base, f = f_spec + diffuse/pi (1 - F(cos_o)) (1 - F(cos_i)).
// The (1 - F) factors model light refracted into the coating on the way in
// and out (the Fresnel reflectance of the flat macrosurface); they keep the
// lobe reciprocal and take from the diffuse term what the specular lobe can at
// most reflect, so the white furnace stays <= 1 (checked in bxdfs_test.cpp).
// Sampling picks the specular lobe with probability
//   P_s = F(cos_o) / (F(cos_o) + (1 - F(cos_o)) max(diffuse)),
// the two lobes' albedo estimates at wo, else the cosine-weighted diffuse lobe.
struct PlasticBxdf {
    glm::vec3 diffuse{0.5f};
    MicrofacetDistribution dist;
    float eta = 1.5f;

    glm::vec3 f(glm::vec3 wo, glm::vec3 wi) const;
    float pdf(glm::vec3 wo, glm::vec3 wi) const;
    std::optional<BsdfSample> sample(glm::vec3 wo, float uc, glm::vec2 u) const;
    // True only if every lobe is a delta (never: the diffuse base is not).
    bool is_specular() const { return false; }
    float specular_probability(glm::vec3 wo) const;
};

// glTF 2.0's metallic-roughness material (Khronos glTF 2.0 specification,
// Appendix B): f = (1 - metallic) f_dielectric + metallic f_metal, one
// distribution for both. f_dielectric is PlasticBxdf (base_color under a
// coat of IOR eta: the specification's fresnel_mix, made reciprocal and
// energy-bounded by PlasticBxdf's (1 - F) factors), f_metal a rough metal of
// Schlick Fresnel with F0 = base_color (the specification's
// conductor_fresnel). Sampling picks the metal with probability `metallic`,
// else the plastic's own sampling; the pdf is the mixture's. Where the
// distribution is a delta both specular lobes lie in the mirror direction,
// and a delta sample carries their sum.
struct MetallicRoughnessBxdf {
    glm::vec3 base_color{0.5f};
    float metallic = 1.0f;  // [0, 1]
    MicrofacetDistribution dist;
    float eta = 1.5f;  // the dielectric's IOR (glTF's 1.5, KHR_materials_ior)

    glm::vec3 f(glm::vec3 wo, glm::vec3 wi) const;
    float pdf(glm::vec3 wo, glm::vec3 wi) const;
    std::optional<BsdfSample> sample(glm::vec3 wo, float uc, glm::vec2 u) const;
    bool is_specular() const { return metallic >= 1.0f && dist.effectively_smooth(); }

  private:
    PlasticBxdf dielectric() const;
};

using Bxdf =
    std::variant<DiffuseBxdf, ConductorBxdf, DielectricBxdf, PlasticBxdf, MetallicRoughnessBxdf>;

glm::vec3 bxdf_f(const Bxdf& bxdf, glm::vec3 wo, glm::vec3 wi);
float bxdf_pdf(const Bxdf& bxdf, glm::vec3 wo, glm::vec3 wi);
std::optional<BsdfSample> bxdf_sample(const Bxdf& bxdf, glm::vec3 wo, float uc, glm::vec2 u);
bool bxdf_is_specular(const Bxdf& bxdf);

}  // namespace glintlab
