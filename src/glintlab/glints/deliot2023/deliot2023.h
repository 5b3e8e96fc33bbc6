// C++ host side of the deliot2023 glint model (Deliot & Belcour 2023, 000): the evaluation of
// the shared deliot2023.glsl and the reader of its parameter block.
#pragma once

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/glints/deliot2023/deliot2023_params.h"

namespace glintlab {

struct GlintDesc;

// The target NDF and the shared glint parameters, as plain values.
struct Deliot2023Target {
    int ndf = 0;  // shader::NDF_BECKMANN or shader::NDF_GGX
    float alpha_x = 0.3f;
    float alpha_y = 0.3f;
    float rho = 0.0f;           // the slopes' correlation (GlintDesc::slope_correlation)
    float log_density = 20.0f;  // ln(facets per unit uv area)
    uint32_t seed = 0;
};

// D_P(h) (000 Eq. 3-4) of shader::deliot2023_ndf, h in the local frame.
float deliot2023_ndf(glm::vec3 h, const Footprint& footprint, const Deliot2023Target& target,
                     const Deliot2023Params& params);

// The 64 x 64 uniform pairs of the noise table (000 §6.3), row-major: PCG32
// stream (0x64656c696f74, seed 2023), each pair (first draw, second draw).
// The one source of the table for the CPU lookup and the GPU texture.
const std::array<glm::vec2, 64 * 64>& deliot2023_noise_table();

// The same with the uniforms from a precomputed 64 x 64 noise table instead of
// a hash (000 §6.3; deliot2023_noise_table.cpp), for speed comparisons.
float deliot2023_ndf_noise_table(glm::vec3 h, const Footprint& footprint,
                                 const Deliot2023Target& target, const Deliot2023Params& params);

// The smooth target D(h) the model converges to (000 Eq. 5-6).
float deliot2023_target_ndf(glm::vec3 h, const Deliot2023Target& target);

// Footprint ellipse (minor length, major length, angle) of deliot2023.glsl.
glm::vec3 deliot2023_footprint_ellipse(glm::vec2 duvdx, glm::vec2 duvdy, bool original_defects);

// The material's D_P: desc.params must hold Deliot2023Params.
float deliot2023_footprint_ndf(glm::vec3 h, const Footprint& footprint, const GlintDesc& desc);

}  // namespace glintlab
