// GlintBxdf's hooks of jakob2014 (glints/glint_kernel.h): D_P over the
// spherical conic of both directions (002 Eq. 7), its per-channel form
// (per-particle areas, 002 §3.5) and the model's own sampling (002 §4: 2α
// lobe ⊛ γ cone) with its density.
#pragma once

#include <optional>

#include "glintlab/glints/jakob2014/jakob2014.h"

namespace glintlab {

struct Jakob2014Kernel {
    static float footprint_ndf(glm::vec3 wo, glm::vec3 wi, glm::vec3 h, const Footprint& footprint,
                               const GlintDesc& desc) {
        return jakob2014_footprint_ndf(wo, wi, h, footprint, desc);
    }
    static glm::vec3 footprint_ndf_rgb(glm::vec3 wo, glm::vec3 wi, glm::vec3 h,
                                       const Footprint& footprint, const GlintDesc& desc) {
        return jakob2014_footprint_ndf_rgb(wo, wi, h, footprint, desc);
    }
    static std::optional<glm::vec3> sample_wi(const GlintDesc& desc, glm::vec3 wo, float uc,
                                              glm::vec2 u) {
        return jakob2014_sample_wi(desc, wo, uc, u);
    }
    static float lobe_pdf(const GlintDesc& desc, glm::vec3 wo, glm::vec3 wi) {
        return jakob2014_pdf(desc, wo, wi);
    }
};

}  // namespace glintlab
