// jakob2014 — Discrete stochastic microfacet models (Jakob, Hašan, Yan,
// Lawrence, Ramamoorthi, Marschner, SIGGRAPH 2014; 002). Offline-only
// C++ (a 4-D tree traversal per query; no GLSL).
//
// The multiscale BRDF (Eq. 2-6) in glintlab's GlintBxdf form
//     f = color · F(wo·h) · G2 · D_P / (4 |wo·n| |wi·n|),
//     D_P = 4 (ωi·h) D̂ / (a(A) σ(Ω_o) (h·n)),   D̂ = count / N       (Eq. 5-6)
// where count is the number of particles in the footprint parallelogram A
// whose normals lie in the spherical conic Ω_h (Eq. 7-9) that reflects wi
// into the cone of radius γ around wo, σ(Ω_o) = 2π(1 - cos γ), and N the
// particles per unit uv area. The 1/(h·n) accounts for particle normals being
// distributed as D(m)(m·n) (MODELS.md, decisions); with it E[D_P] -> D(h)
// as γ -> 0 (the smooth model; validated by `glintlab validate jakob2014`).
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/glints/jakob2014/jakob2014_params.h"
#include "glintlab/glints/jakob2014/query.h"

namespace glintlab {

struct GlintDesc;

namespace jakob2014 {

// Largest log density: N must be an exact integer in double precision (the
// multinomial's Gaussian branch works in doubles): N <= 2^53.
inline constexpr double kMaxLogDensity = 36.7;

// The query model of a glint material (desc.params must hold Jakob2014Params).
Model make_model(const GlintDesc& desc);
NdfSpec ndf_spec(const GlintDesc& desc);

// σ(Ω_o) = 2π(1 - cos γ): the solid angle of the query cone (the paper's text
// reads π(1 - cos γ); the solid angle of a cone of half-angle γ is 2π(1 - cos γ),
// which is also what the authors' plugin divides by).
double cone_solid_angle(double gamma);

// The factor turning a particle count into D_P (header comment).
double count_to_ndf(const Model& m, double footprint_area, glm::dvec3 wi, glm::dvec3 h);

// Thread-local counters of every query made by this thread (002 Table 1).
QueryStats& thread_stats();

// The 64-point (0,2)-net of the pdf's QMC convolution (002 §4): van der
// Corput × Sobol's second dimension, shifted by half a stratum.
glm::dvec2 qmc_point(int i);

}  // namespace jakob2014

// D_P of the material for the footprint (header comment); wi, wo, h local.
float jakob2014_footprint_ndf(glm::vec3 wo, glm::vec3 wi, glm::vec3 h, const Footprint& footprint,
                              const GlintDesc& desc);
// Per channel (chromatic glints, 002 §3.5); the scalar D_P thrice otherwise.
glm::vec3 jakob2014_footprint_ndf_rgb(glm::vec3 wo, glm::vec3 wi, glm::vec3 h,
                                      const Footprint& footprint, const GlintDesc& desc);

// Importance sampling of 002 §4: a visible normal of the smooth NDF at
// 2α gives wi' = reflect(-wo, m); wi is uniform in the cone of radius γ
// around wi'. Returns nullopt below the horizon. (uc, u) as GlintBxdf::sample.
std::optional<glm::vec3> jakob2014_sample_wi(const GlintDesc& desc, glm::vec3 wo, float uc,
                                             glm::vec2 u);
// Its density in solid angle: the 2α reflected visible-normal density
// convolved with the cone, by 64-point QMC (002 §4). `full_sphere` keeps
// directions below the horizon (the density of wi before rejection).
float jakob2014_pdf(const GlintDesc& desc, glm::vec3 wo, glm::vec3 wi, bool full_sphere = false);

}  // namespace glintlab
