// C++ host side of the chermain2020 glint model (Chermain et al. 2020, 004): evaluation of
// the shared chermain2020.glsl over the default dictionary, and the reader of
// its parameter block.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/core/view_differentials.h"
#include "glintlab/glints/chermain2020/chermain2020_params.h"

namespace glintlab {

struct GlintDesc;

// The shared glint parameters the model reads, as plain values.
struct Chermain2020Target {
    float alpha_x = 0.5f;
    float alpha_y = 0.5f;
    // The slopes' correlation, in (−1, 1) (Chermain et al. 2021): a normal
    // map's or a curved surface's Σ_xy when the model's "slope_correlation"
    // is "chermain2021"; 0 is 004's axis-aligned target.
    float rho = 0.0f;
    float log_density = 27.0f;  // ln(facets per unit uv area); authors' UI default
    uint32_t seed = 0;
    // Geometric glint anti-aliasing (Chermain et al. 2021, §4): the half
    // vector's slope change per pixel step (∂s/∂x, ∂s/∂y) and the kernel
    // scale; kernel 0 is 004's unfiltered lookup.
    glm::vec4 slope_differentials{0.0f};
    float kernel = 0.0f;
};

// The random choices of one cell (Algorithm 3) of the default dictionary.
struct Chermain2020CellInfo {
    bool active = false;
    int dist_level = 0;  // == n_levels: the analytic Beckmann target
    int dist_x = 0, dist_y = 0;
    float theta = 0.0f;
};

// D_P(h) (004 Eq. 13), h in the local frame.
float chermain2020_ndf(glm::vec3 h, const Footprint& footprint, const Chermain2020Target& target,
                       const Chermain2020Params& params);

// RGB D_P(h) with the colour table of params (coloured glints); equal to
// chermain2020_ndf in every channel when params.colour_count = 0.
glm::vec3 chermain2020_ndf_rgb(glm::vec3 h, const Footprint& footprint,
                               const Chermain2020Target& target, const Chermain2020Params& params);

// Marginal `dist` of dictionary level `level` at x (the dictionary's
// slopes), averaged over the box [x − width/2, x + width/2] (geometric glint
// anti-aliasing's filter); width 0: the point value.
float chermain2020_marginal_box(int dist, int level, float x, float width);

// The smooth Beckmann D(h) the model converges to (004 §4.3).
float chermain2020_target_ndf(glm::vec3 h, const Chermain2020Target& target);

// Cell `cell` of hierarchy level `level` (Eq. 8 seeding, Algorithm 3).
Chermain2020CellInfo chermain2020_cell(glm::ivec2 cell, int level, const Chermain2020Target& target,
                                       const Chermain2020Params& params);

// P^22_theta,alpha of one cell at a slope (Eq. 11).
float chermain2020_cell_p22(const Chermain2020CellInfo& cell, glm::vec2 slope,
                            const Chermain2020Target& target);

// The slope in the cell's dictionary frame, s' = R^-1 S^-1 s (Eq. 9-11).
glm::vec2 chermain2020_dict_slope(const Chermain2020CellInfo& cell, glm::vec2 slope,
                                  const Chermain2020Target& target);

// Algorithm 2 at one hierarchy level: the weighted, normalised sum of the
// cells' SDFs (RGB with the colour table) over the ellipse (major, minor,
// angle of the major axis; uv units) around uv, at `slope`. The walk inside
// chermain2020_ndf, exposed for tests.
glm::vec3 chermain2020_level_sdf(glm::vec2 slope, glm::vec2 uv, glm::vec3 ellipse, int level,
                                 const Chermain2020Target& target,
                                 const Chermain2020Params& params);

// The material's D_P: desc.params must hold Chermain2020Params. With
// `view` (the pixel's view differentials, wo included) and the params'
// "antialiasing", the marginals are filtered over the half vector's sweep.
float chermain2020_footprint_ndf(glm::vec3 h, const Footprint& footprint, const GlintDesc& desc,
                                 const ViewDifferentials* view = nullptr);
glm::vec3 chermain2020_footprint_ndf_rgb(glm::vec3 h, const Footprint& footprint,
                                         const GlintDesc& desc,
                                         const ViewDifferentials* view = nullptr);

}  // namespace glintlab
