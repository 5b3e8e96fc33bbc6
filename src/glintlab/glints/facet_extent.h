// The facets' angular extent, shared by the models' descriptors so that
// `glintlab compare` gives every model the microstructure of its ground truth
// (docs/VALIDATION.md "compare", facet extent).
//
// `explicit` spreads a delta light over a cone of reflected directions of
// half-angle gamma (gamma_deg): a facet lights up when the mirror direction
// of wo about its normal lies in that cone. At normal incidence, where
// d(omega_h) = d(omega_i) / 4, the facet normals that do so fill a cone of
// half-vector solid angle
//     omega_h(gamma) = 2 pi (1 - cos gamma) / 4 = pi (1 - cos gamma) / 2,
// so one facet (normals distributed as D(m) (m.n)) succeeds with probability
// p = D(h) (h.n) omega_h. Each model's own extent parameter is matched to it:
//   - R of Deliot & Belcour 2023 Eq. 4 (zirr2016, deliot2023, kneiphof2025's
//     point-light grid): p = R D(h) / D(n), hence R = D(n) omega_h;
//   - a cone half-angle of the same definition (jakob2014, wang2020, the
//     wang2020_style variant of kneiphof2025): gamma itself;
//   - a fixed Gaussian lobe of slope std-devs (sx, sy) (chermain2020's
//     dictionary): the explicit cone with the same variance-equivalent area
//     (integral f)^2 / integral f^2, which is omega_h for the cone's
//     indicator and 4 pi sx sy for the Gaussian (near the normal, slope
//     area = solid angle), so 1 - cos gamma = 8 sx sy.
#pragma once

#include <string>
#include <string_view>

#include "glintlab/glints/glint_desc.h"

namespace glintlab {

// omega_h(gamma) above, gamma in radians.
double facet_cone_half_vector_solid_angle(double gamma_rad);

// R of 000 Eq. 4 whose success probability R D(h)/D(n) equals explicit's
// D(h) omega_h(gamma) for this material's NDF (D(n) = 1 / (pi ax ay) for
// Beckmann and GGX). Not clamped: the caller checks its model's range.
double microfacet_roughness_for_cone(const GlintDesc& desc, double gamma_rad);

// The explicit cone half-angle (radians) whose facets have the variance-
// equivalent extent of a Gaussian slope lobe of std-devs (sx, sy).
double cone_for_gaussian_slope_lobe(double sigma_x, double sigma_y);

// Sets the number parameter `key` of desc's model (its descriptor's table)
// to `wanted` clamped to the parameter's range and returns "KEY VALUE", plus
// "(clamped to its range [lo, hi]; wanted W)" when it was clamped.
std::string set_facet_extent_param(GlintDesc& desc, std::string_view key, double wanted);
// The same for a cone half-angle parameter in degrees, from gamma in radians.
std::string set_facet_cone_param(GlintDesc& desc, std::string_view key, double gamma_rad);

}  // namespace glintlab
