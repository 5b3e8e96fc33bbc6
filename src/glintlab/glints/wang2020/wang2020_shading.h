// Three-scale glint shading of 001 §4.3 (environment: Eqs. 18–20; point and
// directional lights: Eq. 21) on top of the DPF tables, the prefiltered
// environment tables and the particle quadtree.
//
// Footprint: the axis-aligned uv bounding box A of the pixel footprint, in
// units of the particle tile (N particles per unit uv square, tile repeats).
// a(A) is its area; the expected particle count is N a(A) (§4.4 "Glint
// Rendering": the footprint area estimates the count), which selects
//   micro (< 4):  Eq. 20 — traverse, accept particle k iff λ(x_k) < P̂ (the
//                 Heaviside H of Eq. 8 is read as "accepted with probability
//                 P̂"; the printed argument order λ − P̂ would accept with
//                 probability 1 − P̂ and break Eq. 19's expectation);
//   meso (4–64):  Eq. 18 — exact count from the quadtree, no acceptance test;
//   macro (> 64): count ≈ N a(A): Lo = L̂o / σ(Ωo).
// That is MicroMode::AsPublished. MicroMode::PerParticle (the default) gives
// every particle k its own normal m_k ~ D(m)(m·n) (hashes of the particle,
// the same on CPU and GPU); the micro scale sums what each facet reflects:
//   environment: Lo = (1/(a N)) Σ_{k in A} L_γ(i_k) M(i_k, o), i_k = reflect(o, m_k)
//                (M's F at o·m_k, the particle's own normal),
//   lights (Eq. 21): particle k is lit iff reflect(i, m_k) lies in the γ cone
//   around o (probability P(i, o, γ), Eq. 6),
// and the scales blend over log2-linear bands of the expected count around
// 4 and 64 (wang2020_scale_weights). The count is the effective one
// (ScaleCount::Effective, below) unless "scale_count" is "particles".
// Derivation and measurements: docs/MODELS.md, wang2020.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "glintlab/glints/wang2020/wang2020_dpf.h"
#include "glintlab/glints/wang2020/wang2020_prefilter.h"
#include "glintlab/glints/wang2020/wang2020_quadtree.h"

namespace glintlab::wang2020 {

enum class MicroMode { PerParticle, AsPublished };
// What the per_particle mode's scale bands count (wang2020_scale_weights):
// Effective (default): the effective number of particles n r of the
// footprint's micro estimate, whose relative variance is 1 / (n r) — r = P
// (the DPF) under a light, r = E[f]² / E[f²] from the prefiltered table
// under the environment — micro up to n r = 64, macro from 256
// (wang2020.glsl wang2020_effective_weights), the micro scale never
// enumerating more than WANG2020_MICRO_ENUMERATION_MAX (wang2020.glsl, shared
// with the GPU) particles; Particles: 001
// §4.3's particle count n with the micro / meso / macro bands.
enum class ScaleCount { Effective, Particles };
enum class PrefilterMode { Mis, AsPublished };
// What each particle of the per_particle micro sum reflects under the
// environment: Point (default): the environment's value in its mirror
// direction, as an explicit facet does, so a small sun lights few particles
// brightly; Cone: L_γ, the environment averaged over the γ cone (spreads a
// sun of radius ρ over ρ + γ, (1 + γ/ρ)² times the particles each catching
// as much less light; the sparkle's variance falls by that factor).
// docs/MODELS.md, wang2020.
enum class ParticleRadiance { Point, Cone };

struct Wang2020Material {
    double alpha = 0.1;           // Beckmann roughness, [0.02, 1]
    double gamma_deg = 1.0;       // search cone half-angle γ, [1, 30]
    uint64_t particles = 100000;  // N per uv tile
    int depth = 11;               // quadtree depth (§6)
    uint32_t seed = 1;
    glm::dvec3 color{1.0};
    DpfResolution dpf_res{};                           // Table 2: 90 × 90 × 180
    std::optional<PrefilterResolution> prefilter_res;  // default: Table 2 by α
    int prefilter_samples = 64;                        // K of Eq. 16
    MicroMode micro = MicroMode::PerParticle;
    PrefilterMode prefilter = PrefilterMode::Mis;      // without a sampler: as published
    DpfRoughness dpf_roughness = DpfRoughness::Exact;  // §4.4 as published: Interpolated
    FresnelDesc fresnel;                               // F of M (Eq. 11); mode None: F = 1
    ScaleCount scale_count = ScaleCount::Effective;    // per_particle only
    ParticleRadiance particle_radiance = ParticleRadiance::Point;  // per_particle only
};

enum class Scale { Micro, Meso, Macro };
inline constexpr double kMicroMax = 4.0;  // §4.3
inline constexpr double kMesoMax = 64.0;  // §4.3
Scale select_scale(double expected_count);

// Footprint A: the uv box [lo, hi] the quadtree is queried with (001 §5)
// and, when known (renders: wang2020_model.cpp box_of), the pixel's
// parallelogram centre + s du + t dv, s, t ∈ [-½, ½), whose AABB the box is.
// The per_particle modes count and sum only the parallelogram's particles
// (the explicit truth's footprint convention): at grazing the AABB of a
// long diagonal parallelogram holds 2x its particles and more, which
// averaged the sparkle away (docs/MODELS.md wang2020). du = dv = 0: the box.
struct UvBox {
    glm::dvec2 lo, hi;
    glm::dvec2 centre{0.0}, du{0.0}, dv{0.0};
    double area() const { return std::max(0.0, hi.x - lo.x) * std::max(0.0, hi.y - lo.y); }
    bool has_parallelogram() const { return du != glm::dvec2(0.0) || dv != glm::dvec2(0.0); }
    // The parallelogram's area |det(du, dv)|, else the box's.
    double footprint_area() const {
        return has_parallelogram() ? std::abs(du.x * dv.y - du.y * dv.x) : area();
    }
    // Whether the uv point lies in the parallelogram (in the box: true).
    bool contains(glm::dvec2 p) const;
};

class Wang2020Model {
  public:
    explicit Wang2020Model(const Wang2020Material& m);

    // Prefilter pass (Eqs. 16–17) for an environment; replaces any previous
    // one. The sampler (optional) serves PrefilterMode::Mis; PerParticle also
    // builds the table its particles reflect: L_γ (ParticleRadiance::Cone)
    // or the point values on a grid of 2 × environment_rows rows (the
    // environment map's rows; 0: an analytic environment, 1024 rows), at
    // most 1024 (a 32 MB table on the GPU).
    void prefilter(const EnvironmentFn& env, const EnvironmentSampler* sampler = nullptr,
                   int environment_rows = 0);
    bool has_environment() const { return prefiltered_ != nullptr; }
    // Spatial tree pass only (§4.5: editing N re-runs just the quadtree).
    void rebuild_quadtree(uint64_t particles, uint32_t seed);
    // The same material with another seed: its own quadtree (the particles
    // are the seed's), sharing this model's DPF and prefiltered tables,
    // which depend on the roughness, γ, Fresnel and environment but never
    // on the seed (a sweep over seeds builds them once).
    std::shared_ptr<Wang2020Model> with_seed(uint32_t seed) const;

    // Environment radiance towards o (world space, n = world normal).
    glm::dvec3 environment_radiance(const UvBox& A, const glm::dvec3& n_world,
                                    const glm::dvec3& o_world, Scale* used = nullptr) const;
    // Eq. 21 for a light of incident radiance-times-solid-angle (irradiance
    // normal to i) `li` from local direction wi; wo local (z = normal).
    glm::dvec3 light_radiance(const UvBox& A, const glm::dvec3& wi, const glm::dvec3& wo,
                              const glm::dvec3& li, Scale* used = nullptr) const;

    const Wang2020Material& material() const { return m_; }
    const DpfTable& dpf() const { return *dpf_; }
    const ParticleQuadtree& quadtree() const { return tree_; }
    const PrefilterTable* prefiltered() const { return prefiltered_.get(); }
    // What the particles reflect (PerParticle with an environment only; null
    // otherwise): L_γ or the point values (ParticleRadiance).
    const ParticleRadianceTable* particle_radiance_table() const { return cone_.get(); }
    double sigma_o() const { return sigma_o_; }  // σ(Ωo) = 2π(1 − cos γ)
    // per_particle with ScaleCount::Effective (the prefiltered table's w is
    // then the effective fraction r, not P̂).
    bool effective_scales() const {
        return m_.micro == MicroMode::PerParticle && m_.scale_count == ScaleCount::Effective;
    }
    // Wang2020Tables::micro of the GPU (wang2020_tables.glsl WANG2020_MICRO_MODE_*).
    int micro_mode_index() const {
        if (m_.micro == MicroMode::AsPublished) return 0;
        return effective_scales() ? 2 : 1;
    }
    double extract_seconds() const { return extract_seconds_; }

  private:
    // Σ_k 1_A(x_k) H(p − λ_k) (micro) as a function of a per-particle
    // acceptance probability.
    uint64_t accepted(const UvBox& A, double p) const;
    // Σ_k 1_A(x_k) over the parallelogram (per_particle's meso count; the
    // box's tree count without one).
    uint64_t footprint_count(const UvBox& A) const;
    // PerParticle micro sums over the particles in A (local frame, z = n):
    // Σ L(i_k) M(i_k, o), L = cone_'s table (frame t, b, n maps to world),
    // and the number of
    // particles whose normal reflects wi into the γ cone around wo.
    glm::dvec3 particle_environment(const UvBox& A, const glm::dvec3& o, const glm::dvec3& t,
                                    const glm::dvec3& b, const glm::dvec3& n) const;
    uint64_t particles_lit(const UvBox& A, const glm::dvec3& wi, const glm::dvec3& wo) const;

    Wang2020Material m_;
    double gamma_rad_;
    double sigma_o_;
    // Declared before dpf_, whose initialiser writes it (members initialise
    // in declaration order: declared after, its `= 0.0` overwrote the time).
    double extract_seconds_ = 0.0;
    // The tables are immutable once built and shared by with_seed.
    std::shared_ptr<const DpfTable> dpf_;
    ParticleQuadtree tree_;
    std::shared_ptr<const PrefilterTable> prefiltered_;
    std::shared_ptr<const ParticleRadianceTable> cone_;

    Wang2020Model(const Wang2020Model& tables, uint32_t seed);
};

}  // namespace glintlab::wang2020
