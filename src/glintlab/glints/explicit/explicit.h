// explicit — the ground truth of the glint models: the statistical model of
// 002 §3.1 (Eq. 2-6) and 003 §3.2 (Eq. 4-5) made literal. The surface carries
// N = round(e^log_density) mirror facets per unit uv area (the uv square
// [0,1)² repeats with period 1), positions uniform, normals m distributed with
// the projected-area density D(m)(m·n) (normalised: ∫ D(m)(m·n) dm = 1). A
// pixel's value is the sum of its facets' mirror reflections.
//
// Generation (facet_field.cpp): a top-down quadtree over the unit square.
// The root holds exactly N facets; a node's n facets are split into its four
// equal-area children by two levels of exact Binomial(·, 1/2) draws
// (binomial_half.h), seeded by the node id, down to leaves holding ~16-32
// facets; a leaf's facets get uniform positions and D(m)(m·n) normals from a
// stream seeded by the leaf id. This is exactly the law of N i.i.d. uniform
// facets (a binomial split of i.i.d. uniform points is the multinomial law
// of the cell counts), so the count in any region R of area a inside one tile
// is Binomial(N, a), and the count whose normals lie in a set S is
// Binomial(N, a · P_D(S)). Only nodes overlapping the footprint are visited
// (O(depth + leaves touched)), so N up to 1e13 per unit uv area works for
// small footprints.
//
// Footprint convention (same as jakob2014, uv_overlap.h): the parallelogram
// uv + s·duvdx + t·duvdy, s, t ∈ [-1/2, 1/2) (half-open, so footprints that
// tile the uv plane partition the facets), area a(A) = |det(duvdx, duvdy)|.
// Degenerate footprints (a(A) = 0) contain no facets.
//
// Radiometry (derivation in docs/MODELS.md, section explicit): with
// m ~ D(m)(m·n), the smooth Cook–Torrance reflected radiance is
//     L_o(wo) = E_m[ F(wo·m) w(m) L_i(r(m)) ],
//     w(m) = (wo·m) G2(wo, r) / ((wo·n)(m·n)),   r(m) = 2(wo·m) m - wo,
// (substitute wi = r(m), dwi = 4 (wo·m) dm in ∫ F G2 D L /(4 wo·n) dwi).
// The footprint estimate is 1/(N a(A)) Σ_{facets in A} F w L_i(r) (003 Eq. 5:
// normalised by the expected count E[N_P] = N a(A), so a footprint without
// facets is black and the expectation is exactly the smooth L_o).
#pragma once

#include <cstdint>
#include <functional>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/glints/glint_desc.h"
#include "glintlab/microfacet/bxdfs.h"

namespace glintlab {

// A procedural field of mirror microfacets over uv (tiles with period 1 in u and v).
struct ExplicitFacetField {
    NdfType ndf = NdfType::Beckmann;  // microfacet/bxdfs.h
    float alpha_x = 0.3f, alpha_y = 0.3f;
    double log_density = 20.0;  // ln(facets per unit uv area), in [0, 30]
    uint32_t seed = 0;
    // Expected facets per footprint (N a(A)) above which the enumeration
    // fails with a glintlab::Error instead of running for minutes.
    double max_facets_per_footprint = 1e6;
    // Above the budget: enumerate one part of the footprint
    // (explicit_enumerated_footprint) instead of failing.
    bool subsample_over_budget = false;
    // Textured parameters (docs/MODELS.md, "Textured parameters"): with a
    // density map the field is generated at N_field = ⌈max N⌉ (log_density
    // = ln N_field) and each facet is kept with probability N(uv)/N_field, a
    // hash of its leaf and index deciding (so the 4 draws of every facet,
    // and every untextured render, stay as they were); with a roughness map
    // each facet's normal is drawn with α(uv) = sqrt(α²) bilinear in the
    // finest level. Null: none.
    const GlintTextures* textures = nullptr;
    // A normal map (docs/MODELS.md, "Normal maps"): each facet's normal,
    // drawn around z as without one, is rotated into the frame of the map's
    // normal at the facet's own position (bilinear in the finest level;
    // tangent_frame_around gives the frame), and the facet is weighed as a
    // facet of a surface whose normal is the map's there. `normal_map_axes`
    // carries the map's (x, y) onto the local frame (GlintDesc). Null: none.
    const NormalMap* normal_map = nullptr;
    glm::vec2 normal_map_axes{1.0f};
    glm::vec3 normal_map_view{0.0f};  // GlintDesc::normal_map_view
    // A curved surface (docs/MODELS.md, "Curved surfaces"): the macro
    // normal's slope at a facet is slope_gradient (uv − slope_origin) in the
    // local frame, added to the normal map's there (slopes add to first
    // order, as LEAN's covariances do), and the facet composes with that
    // normal as with a map's. Zero: a flat footprint.
    glm::mat2 slope_gradient{0.0f};
    glm::vec2 slope_origin{0.0f};
    // The facets are composed with a macro normal of their own.
    bool has_macro_normals() const {
        return normal_map != nullptr || slope_gradient != glm::mat2(0.0f);
    }
};

struct ExplicitFacet {
    glm::vec2 uv;  // position (including the footprint's tile offset)
    glm::vec3 m;   // unit normal, local frame (z = n)
    // The normal map's normal at the facet and its frame's tangent
    // (tangent_frame_around; local frame); z and x without a map.
    glm::vec3 n_map{0.0f, 0.0f, 1.0f};
    glm::vec3 t_map{1.0f, 0.0f, 0.0f};
    // N_field / N(uv): the facet's area relative to the field's nominal
    // 1/N_field (1 without a density map); the estimators weigh by it.
    float weight = 1.0f;
};

// N = round(e^log_density): the exact number of facets in every unit uv tile.
uint64_t explicit_facets_per_tile(const ExplicitFacetField& field);
// Depth of the leaves of the quadtree (leaves are 2^-depth wide).
int explicit_leaf_depth(const ExplicitFacetField& field);
// a(A) = |det(duvdx, duvdy)|.
double explicit_footprint_area(const Footprint& fp);
// Throws glintlab::Error if the field's parameters are out of range.
void validate_explicit_field(const ExplicitFacetField& field);

// A normal with density D(m)(m·n) (solid angle) from two uniforms in [0, 1):
// exact inversion in slope space, where D(m)(m·n) dm = P22(x, y) dx dy with
// P22 the Gaussian (Beckmann) or the bivariate Student-t with 2 degrees of
// freedom (GGX), stretched by (alpha_x, alpha_y) (Heitz 2014 §5.1, Eq. 36).
glm::vec3 sample_explicit_normal(NdfType ndf, float alpha_x, float alpha_y, double u1, double u2);

// The footprint the estimators enumerate and normalise by: fp itself,
// unless it holds more than field.max_facets_per_footprint facets in
// expectation and field.subsample_over_budget is set. Then it is one of the
// K x K equal sub-parallelograms of fp, K = ceil(sqrt(N a(fp) / max)),
// picked by a hash of fp's centre (which the pixel samples jitter): each
// estimate (1/(N a)) sum over a footprint is the mean of its parts'
// estimates, so a uniformly chosen part is unbiased for it.
Footprint explicit_enumerated_footprint(const ExplicitFacetField& field, const Footprint& fp);

// Calls visit(facet) for every facet whose uv lies in the footprint
// parallelogram (convention above). Returns the number visited.
uint64_t for_each_explicit_facet(const ExplicitFacetField& field, const Footprint& fp,
                                 const std::function<void(const ExplicitFacet&)>& visit);

// Number of facets in the footprint whose mirror direction reflect(-wo, m)
// lies within angle gamma of wi (002 Eq. 7-8: the query cone; only facets
// facing wo, m·wo > 0, reflect). wo, wi: unit, local frame.
uint64_t explicit_count(const ExplicitFacetField& field, const Footprint& fp, glm::vec3 wo,
                        glm::vec3 wi, float gamma_rad);

// σ(Ω) = 2π(1 - cos γ), the solid angle of the query cone (002 §3.1 prints
// π(1 - cos γ); the solid angle of a cone is 2π(1 - cos γ), see MODELS.md).
double explicit_cone_solid_angle(double gamma_rad);

// 002's footprint NDF in glintlab's D_P form (f = F G2 D_P / (4 cos cos)):
//     D̂ = count / N (002 Eq. 6),
//     D_P = 4 (wi·h) D̂ / (a(A) σ(Ω) (h·n)),   h = normalize(wo + wi),
// i.e. 002 Eq. 5 with the extra 1/(h·n) because our facet normals have the
// projected-area density D(m)(m·n) (002 leaves the density implicit). Then
// E[D_P] = the cone average of D(h'), which → D(h) as γ → 0. 0 when the
// footprint is degenerate or h is below the surface.
float explicit_footprint_ndf(const ExplicitFacetField& field, const Footprint& fp, glm::vec3 wo,
                             glm::vec3 wi, float gamma_rad);

// The exact expectation of explicit_count / (N a(A)): P(reflect(-wo, m) is
// within gamma of wi) for m ~ D(m)(m·n), by product Gauss–Legendre
// quadrature over the cone (p_dir of the validation; relative accuracy ~1e-6).
double explicit_direction_probability(const ExplicitFacetField& field, glm::vec3 wo, glm::vec3 wi,
                                      double gamma_rad);

// Per-facet weight w(m) above (0 when m·wo <= 0 or the mirror direction is
// below the horizon); `r` receives the mirror direction.
float explicit_facet_weight(const ExplicitFacetField& field, glm::vec3 wo, glm::vec3 m,
                            glm::vec3& r);
// The same for a facet of the field: with a normal map, w(m) in the frame of
// the facet's map normal (its (wo·n) and (m·n) are the map's surface's).
float explicit_facet_weight(const ExplicitFacetField& field, glm::vec3 wo, const ExplicitFacet& f,
                            glm::vec3& r);

// Radiance reflected towards wo by the footprint's facets under an
// environment (003's ground truth): 1/(N a(A)) Σ_k w(m_k) F(wo·m_k) L_env(r_k).
// Its expectation is the smooth microfacet BRDF's reflected radiance
// ∫ F G2 D L_env / (4 wo·n) dwi. `env(dir_local)` returns L_env for a local
// direction (the caller converts frames). This overload has F ≡ 1; the tint
// is the caller's.
glm::vec3 explicit_environment_radiance(const ExplicitFacetField& field, const Footprint& fp,
                                        glm::vec3 wo,
                                        const std::function<glm::vec3(glm::vec3)>& env);
// The same with a per-facet Fresnel factor fresnel(wo·m).
glm::vec3 explicit_environment_radiance(const ExplicitFacetField& field, const Footprint& fp,
                                        glm::vec3 wo,
                                        const std::function<glm::vec3(glm::vec3)>& env,
                                        const std::function<glm::vec3(float)>& fresnel);

}  // namespace glintlab
