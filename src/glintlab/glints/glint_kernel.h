// A model's GlintBxdf hooks: `struct MKernel` in glints/m/m_kernel.h for
// each model of the list (model_list.h), whose static members, all
// optional, GlintBxdf calls for that model (glint_bxdf.cpp expands the
// dispatch from the list):
//   float footprint_ndf(wo, wi, h, footprint, desc)   D_P (default: D)
//   vec3 footprint_ndf_rgb(wo, wi, h, footprint, desc)  per-channel D_P
//       (default: the scalar D_P in every channel)
//   either of the two with `const ViewDifferentials* view` before desc: the
//       pixel's view differentials (null without them), for models that
//       filter over the half vector's sweep across the pixel
//   optional<vec3> sample_wi(desc, wo, uc, u) and float lobe_pdf(desc, wo, wi):
//       the model's own sampling of the glint lobe with a footprint (both or
//       neither; default: the smooth visible normals)
//   bool v_cavity_masking(desc): true where the material takes the V-cavity G2
//       (default: Smith)
// An empty struct is the smooth limit D.
#pragma once

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"

namespace glintlab {

struct GlintDesc;

// The kernel of a model whose D_P depends on the half vector only:
// struct FooKernel : HalfVectorKernel<foo_footprint_ndf> {};
template <float (*D_P)(glm::vec3 h, const Footprint& footprint, const GlintDesc& desc)>
struct HalfVectorKernel {
    static float footprint_ndf(glm::vec3, glm::vec3, glm::vec3 h, const Footprint& footprint,
                               const GlintDesc& desc) {
        return D_P(h, footprint, desc);
    }
};

}  // namespace glintlab
