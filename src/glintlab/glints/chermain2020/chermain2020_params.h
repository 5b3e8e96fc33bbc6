// Parameters of the chermain2020 glint model (its block "chermain2020": {...}
// of a glint material; ranges and defaults justified in docs/MODELS.md). The
// roughness, the NDF (Beckmann only) and the density rho = exp(log_density)
// are the glint material's shared parameters.
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace glintlab {

struct Chermain2020Params {
    // beta (004 §7.1): fraction of cells that carry facets, [0, 1].
    float relative_area = 1.0f;
    // gamma (004 §7.1): largest major/minor ratio of the footprint, [1, 32].
    float max_anisotropy = 8.0f;
    // zeta (004 §7.1, Alg. 3 line 8): std-dev of the distribution LOD, [0, 8].
    float density_randomization = 0.0f;
    // A normal map's and a curved surface's slope correlation Σ_xy shears the
    // target (Chermain et al. 2021, Eq. 18): "chermain2021" (true) or
    // dropped as 004 has no correlation ("none", false).
    bool slope_correlation = true;
    // Geometric glint anti-aliasing (Chermain et al. 2021, §4): each cell's
    // marginals are box-filtered over the half vector's slope sweep across
    // the pixel, times `antialiasing_kernel` (their KernelSize), on the CPU
    // and in the forward pass: "chermain2021" (true) or unfiltered ("none",
    // false, 004).
    bool antialiasing = false;
    float antialiasing_kernel = 1.0f;
    // Masking-shadowing: the height-correlated Smith G2 of the target NDF
    // ("smith", false), the ground truth's, or 004's V-cavity G2 (Eq. 14-16,
    // "v_cavity", true), which departs from it at grazing angles.
    bool v_cavity_masking = false;
    // Coloured glints (004 §7.1, Alg. 3 lines 11-12, 19): each cell tints its
    // SDF with colour_table[floor(colour_count * U_c)]; 0 colours = white.
    int colour_count = 0;
    std::array<glm::vec3, 8> colour_table{};  // CHERMAIN2020_MAX_COLOURS
};

}  // namespace glintlab
