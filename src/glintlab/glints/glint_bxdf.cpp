#include "glintlab/glints/glint_bxdf.h"

#include "glintlab/glints/chermain2020/chermain2020.h"
#include "glintlab/glints/deliot2023/deliot2023.h"
#include "glintlab/glints/explicit/explicit_model.h"
#include "glintlab/glints/jakob2014/jakob2014.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025.h"
#include "glintlab/glints/zirr2016/zirr2016.h"
#include "glintlab/microfacet/microfacet.h"
#include "glintlab/scene/scene.h"

// The glint material's shading, shared with the GPU forward pass.
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/material.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

static_assert(static_cast<int>(FresnelDesc::Mode::None) == shader::GLINT_FRESNEL_NONE &&
              static_cast<int>(FresnelDesc::Mode::Schlick) == shader::GLINT_FRESNEL_SCHLICK &&
              static_cast<int>(FresnelDesc::Mode::Conductor) == shader::GLINT_FRESNEL_CONDUCTOR &&
              static_cast<int>(FresnelDesc::Mode::Dielectric) == shader::GLINT_FRESNEL_DIELECTRIC);

int ndf_id(NdfType t) {
    return t == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN;
}

// The GlintDesc as material.glsl reads it (the GPU fills the same struct
// from uniforms, realtime/gpu_renderer.cpp).
shader::GlintMaterial material(const GlintDesc& desc) {
    shader::GlintMaterial m;
    m.color = desc.color;
    m.base_albedo = desc.base_albedo;
    m.fresnel_mode = static_cast<int>(desc.fresnel.mode);
    m.fresnel_f0 = desc.fresnel.f0;
    m.fresnel_eta = desc.fresnel.eta;
    m.fresnel_k = desc.fresnel.k;
    m.ndf = ndf_id(desc.ndf);
    m.alpha_x = desc.alpha_x;
    m.alpha_y = desc.alpha_y;
    m.g2 = glint_g2_mode(desc.model_id);
    return m;
}

}  // namespace

int glint_g2_mode(GlintModelId model) {
    return model == GlintModelId::Chermain2020 ? shader::GLINT_G2_VCAVITY
                                               : shader::GLINT_G2_SMITH_CORRELATED;
}

float GlintBxdf::footprint_ndf(glm::vec3 wo, glm::vec3 wi, glm::vec3 h) const {
    // A closed set of models (ARCHITECTURE.md §5): each case calls the
    // model's own evaluation of its footprint NDF. Models whose query depends
    // on both directions (jakob2014's spherical conic, 002 Eq. 7) use wo, wi.
    (void)wo;
    (void)wi;
    switch (desc->model_id) {
        case GlintModelId::Smooth:
            break;
        // Models still being built render their smooth limit until their
        // registry row exists (the scene loader cannot select them before).
        case GlintModelId::Explicit:
            return explicit_footprint_ndf(wo, wi, footprint, *desc);
        case GlintModelId::Wang2020:
            break;
        case GlintModelId::Kneiphof2025:
            return kneiphof2025_footprint_ndf(h, footprint, *desc);
        case GlintModelId::Deliot2023:
            return deliot2023_footprint_ndf(h, footprint, *desc);
        case GlintModelId::Chermain2020:
            return chermain2020_footprint_ndf(h, footprint, *desc);
        case GlintModelId::Zirr2016:
            return zirr2016_footprint_ndf(h, footprint, *desc);
        case GlintModelId::Jakob2014:
            return jakob2014_footprint_ndf(wo, wi, h, footprint, *desc);
    }
    return shader::D_Microfacet(ndf_id(desc->ndf), h, desc->alpha_x, desc->alpha_y);
}

glm::vec3 GlintBxdf::footprint_ndf_rgb(glm::vec3 wo, glm::vec3 wi, glm::vec3 h) const {
    if (desc->model_id == GlintModelId::Chermain2020)
        return chermain2020_footprint_ndf_rgb(h, footprint, *desc);
    if (desc->model_id == GlintModelId::Jakob2014)
        return jakob2014_footprint_ndf_rgb(wo, wi, h, footprint, *desc);
    return glm::vec3(footprint_ndf(wo, wi, h));
}

glm::vec3 GlintBxdf::fresnel(float cos_oh) const {
    return shader::glint_fresnel(material(*desc), cos_oh);
}

glm::vec3 GlintBxdf::base_f(glm::vec3 wo, glm::vec3 wi) const {
    return shader::glint_base_f(material(*desc), wo, wi);
}

float GlintBxdf::glint_lobe_probability(glm::vec3 wo) const {
    return shader::glint_lobe_probability(material(*desc), wo);
}

glm::vec3 GlintBxdf::f(glm::vec3 wo, glm::vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    const shader::GlintMaterial m = material(*desc);
    glm::vec3 h = wo + wi;
    if (glm::dot(h, h) == 0.0f) return shader::glint_base_f(m, wo, wi);
    h = glm::normalize(h);
    const glm::vec3 d = has_footprint
                            ? footprint_ndf_rgb(wo, wi, h)
                            : glm::vec3(shader::D_Microfacet(m.ndf, h, m.alpha_x, m.alpha_y));
    return shader::glint_brdf(m, wo, wi, h, d);
}

float GlintBxdf::pdf(glm::vec3 wo, glm::vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const float pg = glint_lobe_probability(wo);
    return pg * glint_lobe_pdf(wo, wi) + (1.0f - pg) * wi.z * shader::INV_PI;
}

float GlintBxdf::glint_lobe_pdf(glm::vec3 wo, glm::vec3 wi) const {
    // jakob2014 samples its discrete model by 002 §4 (2α lobe ⊛ γ cone); its
    // later bounces (no footprint) use the smooth model.
    if (desc->model_id == GlintModelId::Jakob2014 && has_footprint)
        return jakob2014_pdf(*desc, wo, wi);
    glm::vec3 h = wo + wi;
    if (glm::dot(h, h) == 0.0f) return 0.0f;
    h = glm::normalize(h);
    // Reflection Jacobian dωh/dωi = 1 / (4 |wo·h|) (Walter et al. 2007 Eq. 14).
    return shader::pdf_vndf(ndf_id(desc->ndf), wo, h, desc->alpha_x, desc->alpha_y) /
           (4.0f * std::abs(glm::dot(wo, h)));
}

std::optional<BsdfSample> GlintBxdf::sample(glm::vec3 wo, float uc, glm::vec2 u) const {
    if (wo.z <= 0.0f) return std::nullopt;
    glm::vec3 wi;
    const float pg = glint_lobe_probability(wo);
    if (uc >= pg) {
        // The diffuse base: cosine-weighted hemisphere (Malley).
        const float r = std::sqrt(u.x), phi = 2.0f * shader::PI * u.y;
        wi = glm::vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x)));
    } else if (desc->model_id == GlintModelId::Jakob2014 && has_footprint) {
        uc = std::min(uc / pg, 0x1.fffffep-1f);  // reuse the lobe choice's uniform
        const std::optional<glm::vec3> w = jakob2014_sample_wi(*desc, wo, uc, u);
        if (!w) return std::nullopt;
        wi = *w;
    } else {
        const glm::vec3 h =
            shader::sample_vndf(ndf_id(desc->ndf), wo, desc->alpha_x, desc->alpha_y, u);
        wi = glm::reflect(-wo, h);
    }
    if (wi.z <= 0.0f) return std::nullopt;
    BsdfSample s;
    s.wi = wi;
    s.f = f(wo, wi);
    s.pdf = pdf(wo, wi);
    s.is_delta = false;
    s.is_transmission = false;
    if (s.pdf <= 0.0f) return std::nullopt;
    return s;
}

}  // namespace glintlab
