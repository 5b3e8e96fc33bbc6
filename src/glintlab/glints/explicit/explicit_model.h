// The `explicit` glint model's renderer glue (registry.cpp row): parameter
// block, footprint NDF for GlintBxdf, and the first-hit lighting by facet
// enumeration (glint_lighting.h). Lighting, all through one rule: a facet k
// in the footprint contributes w(m_k) F(wo·m_k) L(r_k) / (N a(A))
// (explicit.h), where L(r_k) is the radiance the mirror direction r_k sees:
//  - environment: L_env(r_k), unshadowed (as 003's ground truth, §7);
//  - sphere light / sun (solid angle > 0): the light's radiance if r_k lies in
//    the cone the light subtends (exact for a sphere), one shadow ray per
//    shading call towards the light centre;
//  - point / delta directional light: the light spread uniformly over the
//    cone of half-angle γ around its direction, radiance E⊥ / σ(Ω) (002 §3.1,
//    Fig. 4: γ acts as a light of that size with the same power); one shadow
//    ray towards the light.
// The tint (desc.color) multiplies the result.
#pragma once

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/glints/explicit/explicit.h"

namespace glintlab {

struct GlintDesc;
struct GlintLightingContext;
struct Scene;

// The facet field of a glint material shaded at a footprint (its centre is
// the origin of the curved surface's slope, GlintDesc::slope_gradient).
ExplicitFacetField explicit_field(const GlintDesc& desc, const Footprint& footprint);
float explicit_gamma_rad(const GlintDesc& desc);

// GlintBxdf's D_P (explicit_footprint_ndf with the material's γ).
float explicit_footprint_ndf(glm::vec3 wo, glm::vec3 wi, const Footprint& footprint,
                             const GlintDesc& desc);

bool explicit_shades_light(const GlintDesc& desc, const Scene& scene, int light);
glm::vec3 explicit_light_radiance(const GlintLightingContext& ctx, int light);

}  // namespace glintlab
