// C++ host side of the zirr2016 glint model ([ZK16] as restated in 000 §3 and
// 004 §2): the evaluation of the shared zirr2016.glsl and the reader of its
// parameter block.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/glints/zirr2016/zirr2016_params.h"

namespace glintlab {

struct GlintDesc;

// The target NDF and the shared glint parameters, as plain values.
struct Zirr2016Target {
    int ndf = 0;  // shader::NDF_BECKMANN or shader::NDF_GGX
    float alpha_x = 0.3f;
    float alpha_y = 0.3f;
    float rho = 0.0f;           // the slopes' correlation (GlintDesc::slope_correlation)
    float log_density = 20.0f;  // ln(facets per unit uv area)
    uint32_t seed = 0;
};

// D_P(h) (000 Eq. 3-4, 7, 15) of shader::zirr2016_ndf, h in the local frame.
float zirr2016_ndf(glm::vec3 h, const Footprint& footprint, const Zirr2016Target& target,
                   const Zirr2016Params& params);

// The smooth target D(h).
float zirr2016_target_ndf(glm::vec3 h, const Zirr2016Target& target);

// The material's D_P: desc.params must hold Zirr2016Params.
float zirr2016_footprint_ndf(glm::vec3 h, const Footprint& footprint, const GlintDesc& desc);

}  // namespace glintlab
