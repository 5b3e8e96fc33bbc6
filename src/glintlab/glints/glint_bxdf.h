// The BRDF of a glint material (ARCHITECTURE.md, "Materials and the glint
// material"; its shading, all but the
// model dispatch of D_P, is glints/material.glsl, shared with the GPU forward
// pass): a microfacet BRDF whose
// NDF is replaced by the model's footprint NDF D_P(h) (000 Eq. 1–3; 002 Eq. 2;
// 004 Eq. 1):
//     f(wo, wi) = color · F(wo·h) · G2(wo, wi) · D_P(h) / (4 |wo·n| |wi·n|).
// The `smooth` model has D_P = D. Without a footprint (secondary bounces)
// every model falls back to its smooth limit D. Sampling uses the smooth
// visible normals, so the estimator stays unbiased for any D_P.
// With a diffuse base (GlintDesc::base_albedo, 002 Fig. 7) the plastic
// layering of microfacet/bxdfs.h is added:
//     f += base_albedo / π · (1 − F(cos_o)) (1 − F(cos_i)),
// F the coating's dielectric Fresnel, and sampling picks the glint lobe with
// PlasticBxdf's probability F(cos_o) / (F(cos_o) + (1 − F(cos_o)) max(base)),
// else the cosine lobe.
//
// The model dispatch is expanded from the list of models (model_list.h):
// each model's `MKernel` (glints/glint_kernel.h lists its optional hooks).
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/core/view_differentials.h"
#include "glintlab/glints/registry.h"
#include "glintlab/microfacet/bxdfs.h"

namespace glintlab {

struct GlintDesc;
struct FresnelDesc;

// The masking-shadowing G2 of a glint material (material.glsl GLINT_G2_*):
// the CPU's GlintBxdf, the GPU's u_glint_g2 and an export's manifest all
// take it from here.
int glint_g2_mode(const GlintDesc& desc);

// F(cos) of a material's Fresnel description (material.glsl glint_fresnel):
// models that apply F inside their own integrals (wang2020's M, 001 Eq. 11)
// take it from here.
glm::vec3 glint_fresnel(const FresnelDesc& fresnel, float cos_oh);

struct GlintBxdf {
    const GlintDesc* desc = nullptr;
    bool has_footprint = false;
    Footprint footprint{};
    // The view's and the normal's change across the pixel (with the
    // footprint, at the camera's first hit).
    bool has_view = false;
    ViewDifferentials view{};

    // D_P(h) for the material's model over the footprint, h = normalize(wo + wi).
    float footprint_ndf(glm::vec3 wo, glm::vec3 wi, glm::vec3 h) const;
    // Per-channel D_P for models with chromatic glints (chermain2020's colour
    // table, 004 §7.1; jakob2014's per-particle areas, 002 §3.5); the scalar
    // D_P in every channel otherwise.
    glm::vec3 footprint_ndf_rgb(glm::vec3 wo, glm::vec3 wi, glm::vec3 h) const;
    glm::vec3 fresnel(float cos_oh) const;
    // The diffuse base's term (0 without a base) and the glint lobe's
    // selection probability in sampling (1 without a base).
    glm::vec3 base_f(glm::vec3 wo, glm::vec3 wi) const;
    float glint_lobe_probability(glm::vec3 wo) const;

    glm::vec3 f(glm::vec3 wo, glm::vec3 wi) const;
    float pdf(glm::vec3 wo, glm::vec3 wi) const;
    // The glint lobe's own sampling density (without the base's mixture).
    float glint_lobe_pdf(glm::vec3 wo, glm::vec3 wi) const;
    std::optional<BsdfSample> sample(glm::vec3 wo, float uc, glm::vec2 u) const;
    bool is_specular() const { return false; }
};

}  // namespace glintlab
