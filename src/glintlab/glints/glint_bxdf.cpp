#include "glintlab/glints/glint_bxdf.h"

#include "glintlab/glints/glint_desc.h"
#include "glintlab/glints/model_list.h"
#include "glintlab/microfacet/microfacet.h"

// The glint material's shading, shared with the GPU forward pass.
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/material.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

// Every model's GlintBxdf hooks (glints/m/m_kernel.h, struct MKernel).
#define GLINTLAB_MODEL_HEADER_KIND kernel
#include "glintlab/glints/model_headers.h"
#undef GLINTLAB_MODEL_HEADER_KIND

namespace glintlab {
namespace {

// Calls f(MKernel{}) for the kernel of `model`: the dispatch, expanded from
// the list of models (static, no strings in the hot path). An id outside the
// list gets the smooth model's kernel (the smooth limit).
template <class F>
decltype(auto) with_kernel(GlintModelId model, F&& f) {
    switch (model) {
#define GLINTLAB_KERNEL_CASE(m, M) \
    case GlintModelId::M:          \
        return f(M##Kernel{});
        GLINTLAB_GLINT_MODELS(GLINTLAB_KERNEL_CASE)
#undef GLINTLAB_KERNEL_CASE
    }
    return f(SmoothKernel{});
}

// Whether the model samples its glint lobe itself (K::sample_wi, K::lobe_pdf).
bool samples_own_lobe(GlintModelId model) {
    return with_kernel(model, []<class K>(K) {
        return requires(const GlintDesc& d, glm::vec3 w, glm::vec2 u) {
            K::sample_wi(d, w, 0.0f, u);
            K::lobe_pdf(d, w, w);
        };
    });
}

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
    m.rho = desc.slope_correlation;
    m.g2 = glint_g2_mode(desc);
    return m;
}

}  // namespace

glm::vec3 glint_fresnel(const FresnelDesc& fresnel, float cos_oh) {
    GlintDesc desc;
    desc.fresnel = fresnel;
    return shader::glint_fresnel(material(desc), cos_oh);
}

int glint_g2_mode(const GlintDesc& desc) {
    return with_kernel(desc.model_id, [&]<class K>(K) {
        if constexpr (requires { K::v_cavity_masking(desc); })
            if (K::v_cavity_masking(desc)) return shader::GLINT_G2_VCAVITY;
        return shader::GLINT_G2_SMITH_CORRELATED;
    });
}

float GlintBxdf::footprint_ndf(glm::vec3 wo, glm::vec3 wi, glm::vec3 h) const {
    // Each model's own evaluation of its footprint NDF (K::footprint_ndf),
    // else (smooth, wang2020) the smooth limit D. Models whose query depends
    // on both directions (jakob2014's spherical conic, 002 Eq. 7) use wo, wi.
    const ViewDifferentials* v = has_view ? &view : nullptr;
    return with_kernel(desc->model_id, [&]<class K>(K) -> float {
        if constexpr (requires { K::footprint_ndf(wo, wi, h, footprint, v, *desc); })
            return K::footprint_ndf(wo, wi, h, footprint, v, *desc);
        else if constexpr (requires { K::footprint_ndf(wo, wi, h, footprint, *desc); })
            return K::footprint_ndf(wo, wi, h, footprint, *desc);
        else
            return shader::D_Microfacet_correlated(ndf_id(desc->ndf), h, desc->alpha_x,
                                                   desc->alpha_y, desc->slope_correlation);
    });
}

glm::vec3 GlintBxdf::footprint_ndf_rgb(glm::vec3 wo, glm::vec3 wi, glm::vec3 h) const {
    const ViewDifferentials* v = has_view ? &view : nullptr;
    return with_kernel(desc->model_id, [&]<class K>(K) -> glm::vec3 {
        if constexpr (requires { K::footprint_ndf_rgb(wo, wi, h, footprint, v, *desc); })
            return K::footprint_ndf_rgb(wo, wi, h, footprint, v, *desc);
        else if constexpr (requires { K::footprint_ndf_rgb(wo, wi, h, footprint, *desc); })
            return K::footprint_ndf_rgb(wo, wi, h, footprint, *desc);
        else
            return glm::vec3(footprint_ndf(wo, wi, h));
    });
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
                            : glm::vec3(shader::D_Microfacet_correlated(
                                  m.ndf, h, m.alpha_x, m.alpha_y, desc->slope_correlation));
    return shader::glint_brdf(m, wo, wi, h, d);
}

float GlintBxdf::pdf(glm::vec3 wo, glm::vec3 wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const float pg = glint_lobe_probability(wo);
    return pg * glint_lobe_pdf(wo, wi) + (1.0f - pg) * wi.z * shader::INV_PI;
}

float GlintBxdf::glint_lobe_pdf(glm::vec3 wo, glm::vec3 wi) const {
    // A model that samples its own lobe (jakob2014: its discrete model by 002
    // §4, 2α lobe ⊛ γ cone) has its density; its later bounces (no
    // footprint) use the smooth model.
    if (has_footprint && samples_own_lobe(desc->model_id))
        return with_kernel(desc->model_id, [&]<class K>(K) -> float {
            if constexpr (requires { K::lobe_pdf(*desc, wo, wi); })
                return K::lobe_pdf(*desc, wo, wi);
            else
                return 0.0f;  // not reached: samples_own_lobe
        });
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
    } else if (has_footprint && samples_own_lobe(desc->model_id)) {
        uc = std::min(uc / pg, 0x1.fffffep-1f);  // reuse the lobe choice's uniform
        const std::optional<glm::vec3> w =
            with_kernel(desc->model_id, [&]<class K>(K) -> std::optional<glm::vec3> {
                if constexpr (requires { K::sample_wi(*desc, wo, uc, u); })
                    return K::sample_wi(*desc, wo, uc, u);
                else
                    return std::nullopt;  // not reached: samples_own_lobe
            });
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
