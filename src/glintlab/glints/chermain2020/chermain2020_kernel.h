// GlintBxdf's hooks of chermain2020 (glints/glint_kernel.h): D_P, its
// per-channel form (the colour table, 004 §7.1) and V-cavity masking (004
// §7; material.glsl GLINT_G2_VCAVITY, the GPU's too).
#pragma once

#include "glintlab/glints/chermain2020/chermain2020.h"
#include "glintlab/glints/glint_kernel.h"

namespace glintlab {

struct Chermain2020Kernel : HalfVectorKernel<chermain2020_footprint_ndf> {
    static constexpr bool v_cavity_masking = true;
    static glm::vec3 footprint_ndf_rgb(glm::vec3, glm::vec3, glm::vec3 h,
                                       const Footprint& footprint, const GlintDesc& desc) {
        return chermain2020_footprint_ndf_rgb(h, footprint, desc);
    }
};

}  // namespace glintlab
