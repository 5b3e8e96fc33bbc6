// Numerical experiments on the chermain2020 model shared by its tests and by
// `glintlab validate chermain2020` (docs/VALIDATION.md, "chermain2020").
#pragma once

#include <cstdint>
#include <vector>

namespace glintlab {

// Mean of D_P(h) over random footprints against the Beckmann D(h) (004 §4.3).
struct Chermain2020ConvergenceCase {
    float alpha_x = 0.0f, alpha_y = 0.0f;
    float tan_theta = 0.0f;  // of h, in units of alpha along the azimuth phi
    float phi = 0.0f;
    float rho = 0.0f;  // slope correlation (Chermain et al. 2021)
    double mean_dp = 0.0, target = 0.0, rel_err = 0.0;
};
std::vector<Chermain2020ConvergenceCase> chermain2020_convergence(int footprints, uint64_t seed);

// Weak white furnace (004 Eq. 17) of one cell of hierarchy level 4.
struct Chermain2020FurnaceCase {
    float alpha = 0.0f, log_density = 0.0f, zeta = 0.0f, theta_o = 0.0f;
    int dist_level = 0;  // the cell's l_dist (n_levels: analytic target)
    double value = 0.0, rel_err = 0.0;
    bool grazing = false;  // theta_o >= 1.5 rad
};
struct Chermain2020FurnaceSweep {
    std::vector<float> alphas, log_densities, zetas, theta_os;
    int cells_per_case = 2;
    int quadrature_per_bin = 3;  // Gauss-Legendre points per table bin and axis
};
Chermain2020FurnaceSweep chermain2020_default_furnace_sweep();
std::vector<Chermain2020FurnaceCase> chermain2020_furnace(const Chermain2020FurnaceSweep& sweep,
                                                          uint64_t seed);

// max |f(wo, wi) - f(wi, wo)| / max(f) of the glint BxDF (Schlick Fresnel).
double chermain2020_reciprocity(int pairs, uint64_t seed);

// Count of non-finite or negative D_P over random inputs, including
// degenerate footprints, grazing and below-horizon h, extreme parameters.
int64_t chermain2020_robustness(int64_t evaluations, uint64_t seed);

}  // namespace glintlab
