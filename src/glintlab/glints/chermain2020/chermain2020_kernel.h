// GlintBxdf's hooks of chermain2020 (glints/glint_kernel.h): D_P, its
// per-channel form (the colour table, 004 §7.1) and its masking choice
// (Smith, or 004 §7's V-cavity: material.glsl GLINT_G2_*, the GPU's too),
// with the pixel's view differentials for Chermain et al. 2021's geometric
// glint anti-aliasing.
#pragma once

#include "glintlab/glints/chermain2020/chermain2020.h"
#include "glintlab/glints/glint_kernel.h"

namespace glintlab {

struct Chermain2020Kernel {
    static bool v_cavity_masking(const GlintDesc& desc) {
        return std::get<Chermain2020Params>(desc.params).v_cavity_masking;
    }
    static float footprint_ndf(glm::vec3, glm::vec3, glm::vec3 h, const Footprint& footprint,
                               const ViewDifferentials* view, const GlintDesc& desc) {
        return chermain2020_footprint_ndf(h, footprint, desc, view);
    }
    static glm::vec3 footprint_ndf_rgb(glm::vec3, glm::vec3, glm::vec3 h,
                                       const Footprint& footprint, const ViewDifferentials* view,
                                       const GlintDesc& desc) {
        return chermain2020_footprint_ndf_rgb(h, footprint, desc, view);
    }
};

}  // namespace glintlab
