// C++ host side of the kneiphof2025 glint model (Kneiphof & Klein 2025, 003, and its K = 1
// area-light case kneiphof2024): the evaluation of the shared
// kneiphof2025.glsl over the CPU prefiltered environment
// (kneiphof2025_prefilter.h), the renderer hooks (glint_lighting.h) and the
// reader of its parameter block.
//
// Lights (docs/MODELS.md "kneiphof2025"):
// - environment: Eq. 17 (K levels, multinomial on the grid without h);
// - sphere lights and directional lights with a solid angle (the sun): one
//   area light, K = 1 (003 Eq. 6-9, 23) on the full deliot2023 grid;
// - point lights and delta directional lights: the deliot2023 BRDF with the
//   fixed laws (003 Table 1: "identical to [DB23]"), through GlintBxdf.
#pragma once

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_params.h"

namespace glintlab {

class Kneiphof2025Environment;
struct GlintDesc;
struct GlintLightingContext;
struct Scene;

// Schlick F0 of the material's Fresnel (the split-sum E_rho = F0 A + B, Eq. 11):
// none -> 1, schlick -> f0, conductor / dielectric -> F at normal incidence.
glm::vec3 kneiphof2025_f0(const GlintDesc& desc);

// Environment radiance of Eq. 17 towards wo for the world normal n and mirror
// direction wr, cos_o = n.wo. desc.params must hold Kneiphof2025Params.
glm::vec3 kneiphof2025_environment_radiance(const Kneiphof2025Environment& env, glm::vec3 n,
                                            glm::vec3 wr, float cos_o, const Footprint& footprint,
                                            const GlintDesc& desc);
// Its smooth limit L_o (Eq. 11; the lobe estimate or the split sum, by the
// params' `smooth`), the mean of the above.
glm::vec3 kneiphof2025_environment_smooth(const Kneiphof2025Environment& env, glm::vec3 n,
                                          glm::vec3 wr, float cos_o, const GlintDesc& desc);
// The shared GLSL's KNEIPHOF2025_SMOOTH_* constant for the params' `smooth`.
int kneiphof2025_smooth_mode(const Kneiphof2025Params& p);

// One area light of constant radiance (K = 1): the factor b(N_P, p) / (E[N_P] p)
// for the light's centre half vector h_c (local) and probability p (Eq. 8-9);
// cos_max, the cosine of the light's angular radius, sizes the angular cells
// ("area_grid"; 1: a point-like light, cells of R).
float kneiphof2025_area_factor(glm::vec3 h_center, const Footprint& footprint, float p,
                               const GlintDesc& desc, float cos_max = 1.0f);
// The angular cell size of that factor (kneiphof2025.glsl
// kneiphof2025_area_grid_roughness, by the params' "area_grid").
float kneiphof2025_area_grid_roughness(float cos_max, const Kneiphof2025Params& k);

// The dual-gated (Algorithm 1) K = 1 factor on the grid without h, for the
// wang2020-style variant and tests.
float kneiphof2025_binomial_factor(const Footprint& footprint, float p, const GlintDesc& desc);

// GlintBxdf's D_P for point / delta directional lights: deliot2023's with the
// reused grid parameters.
float kneiphof2025_footprint_ndf(glm::vec3 h, const Footprint& footprint, const GlintDesc& desc);

// Registry hooks (glint_lighting.h).
bool kneiphof2025_shades_light(const GlintDesc& desc, const Scene& scene, int light);
glm::vec3 kneiphof2025_light_radiance(const GlintLightingContext& ctx, int light);

}  // namespace glintlab
