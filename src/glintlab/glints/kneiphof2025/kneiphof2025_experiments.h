// Experiments behind `glintlab validate kneiphof2025` and the tests
// (docs/VALIDATION.md "kneiphof2025"): the white furnace (003 Fig. 7), the
// gate fixes (003 Fig. 13-14, Eq. 23-25) and the comparison with explicitly
// instantiated facets on a sphere (003 Fig. 6 protocol).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "glintlab/core/image.h"

namespace glintlab {

class Kneiphof2025Environment;
class EnvironmentMap;
struct GlintDesc;

struct FurnaceStats {
    double mean_factor = 0.0;  // mean over footprints of L_P / L_smooth (luminance)
    int nan_count = 0;
};

// `footprints` random footprints (random uv, view angle and mirror direction)
// of ~exp(log_count) expected facets each, under `env` (a furnace when it is
// constant). desc.params must hold Kneiphof2025Params.
FurnaceStats kneiphof2025_furnace_stats(const Kneiphof2025Environment& env, const GlintDesc& desc,
                                        float log_count, int footprints, uint32_t seed);

struct GateBias {
    double fixed_mean = 0.0;     // mean of b / (E[N_P] p), 003 Eq. 23 + Eq. 25 law
    double original_mean = 0.0;  // the same with the published law (000 Eq. 16-18 in fp32)
};

// Area-light factor (K = 1, full grid) at success probability p with
// ~n_expected facets per footprint, averaged over random footprints.
GateBias kneiphof2025_gate_bias(float p, float n_expected, int footprints, uint32_t seed);

// 003 Fig. 6 protocol on a 64 x 64 orthographic sphere.
struct SphereComparison {
    std::string environment;
    float sqrt_alpha = 0.0f;
    float log_rho = 0.0f;         // ln of the density factor rho_N
    int levels = 0;               // K
    bool conditional = false;     // Gaussian moments: Algorithm 1 (false) or conditional
    double facets_per_pixel = 0;  // expected facets in a centre pixel's footprint
    int realizations = 0;
    double mean_ours = 0.0;  // image mean luminance, averaged over realizations
    // Standard error of that mean: the larger of the realizations' spread and
    // the pixels' deviations from the smooth mean taken as independent.
    double mean_ours_se = 0.0;
    double mean_gt = 0.0;  // exact expectation of the explicit ground truth
    double mean_gt_realized = 0.0;
    double mean_rel_err = 0.0;  // |mean_ours - mean_gt| / mean_gt
    // Image mean of our smooth term L_o (Eq. 11) and its relative error
    // against mean_gt: the part of mean_rel_err that is not the glint factor's.
    double mean_smooth = 0.0;
    double smooth_rel_err = 0.0;
    double variance_ratio = 0.0;  // sum of per-pixel squared deviations, ours / ground truth
    // The same against glintlab's `explicit` model (glints/explicit/explicit.h):
    // N = rho facets per unit uv area with normals D(m)(m·n) (its convention;
    // the 003 ground truth above draws Poisson(rho |P|) facets with normals
    // D(h)/D_H), realized with the same number of realizations.
    double mean_explicit = 0.0;
    double variance_ratio_explicit = 0.0;
    int nan_count = 0;
};

struct SphereComparisonOptions {
    std::vector<std::filesystem::path> environments;
    std::vector<float> sqrt_alphas{0.1f, 0.5f, 0.7f};
    std::vector<float> log_rhos{-4.0f, 0.0f, 4.0f};
    int resolution = 64;
    double facets_per_pixel = 16.0;  // at rho_N = 1, in the sphere's centre pixel
    uint32_t seed = 1;
    std::filesystem::path grid_png;  // written when not empty
};

std::vector<SphereComparison> kneiphof2025_sphere_comparison(const SphereComparisonOptions& o);

// 003 Fig. 7: the sphere in a white furnace (L = 1), K = 8; the image mean of
// the average of `realizations` seeds against the smooth model's E_rho.
struct SphereFurnace {
    float log_rho = 0.0f;
    int realizations = 0;
    double mean_glints = 0.0;
    double mean_smooth = 0.0;
    double rel_err = 0.0;
    int nan_count = 0;
};
std::vector<SphereFurnace> kneiphof2025_sphere_furnace(int res, float sqrt_alpha,
                                                       const std::vector<float>& log_rhos,
                                                       double facets_per_pixel, int realizations,
                                                       uint32_t seed);

}  // namespace glintlab
