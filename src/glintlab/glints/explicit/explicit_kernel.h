// GlintBxdf's hooks of the explicit ground truth (glints/glint_kernel.h):
// D_P of the enumerated facets, a query over both directions.
#pragma once

#include "glintlab/glints/explicit/explicit_model.h"

namespace glintlab {

struct ExplicitKernel {
    static float footprint_ndf(glm::vec3 wo, glm::vec3 wi, glm::vec3, const Footprint& footprint,
                               const GlintDesc& desc) {
        return explicit_footprint_ndf(wo, wi, footprint, desc);
    }
};

}  // namespace glintlab
