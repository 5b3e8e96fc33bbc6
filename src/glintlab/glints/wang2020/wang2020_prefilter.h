// Environment prefiltering into the 4-D tables of 001 §4.2:
//   L̂o(n, o) = Σ_j Li(i_j) P(i_j, o, γ) M(i_j, o) / (pdf(i_j) K)   (Eq. 16, K = 64)
//   P̂(n, o)  = Σ_j 2π P(i_j, o, γ) / B                             (Eq. 17, B = 36 × 9)
// n is the world-space surface normal (θn ∈ [0, π], φn ∈ [0, 2π)); o is the
// view direction in the tangent frame of n (θo ∈ [0, π/2), φo ∈ [0, 2π)).
// Resolution θn × φn × θo × φo from Table 2 (31×60×10×36 for α = 0.1,
// 10×18×4×12 for α = 0.5).
//
// M (Eq. 11): as printed, (i·h) F G / ((i·n)(o·n)). Eq. 13 has no cosine
// factor and P counts normals drawn with density D(h)(h·n), so the product
// P/σ(Ωo) · M reproduces the smooth Beckmann integrand f(i,o)(i·n) only with
//   M(i, o) = (i·h) F(i·h) G2(i, o) / ((h·n)(o·n));
// we use this form (decision documented in docs/MODELS.md; checked by the
// white-furnace test). F is the material's Fresnel (none: F = 1), evaluated
// at i·h inside the integral (RGB, so L̂o carries a conductor's colour); the
// glint colour multiplies the result.
// Importance sampling ("prefilter": "as_published"): i = reflect(o, h) with
// h ~ D(h)(h·n) (Beckmann), pdf_b(i) = D(h)(h·n) / (4 (o·h)); the K samples
// are a √K × √K jittered stratified grid.
// "prefilter": "mis" (default): the same K BRDF samples plus K samples of the
// environment's own importance distribution pdf_e (EnvironmentMap::sample,
// proportional to texel luminance: a small sun is found), combined by the
// balance heuristic (Veach 1997): L̂o = Σ_{all 2K} Li P M / (K pdf_b + K pdf_e).
// Without a sampler (a constant environment) "mis" equals "as_published".
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "glintlab/glints/glint_desc.h"
#include "glintlab/glints/wang2020/wang2020_dpf.h"

namespace glintlab {
class EnvironmentMap;
}

namespace glintlab::wang2020 {

using EnvironmentFn = std::function<glm::vec3(const glm::dvec3& world_dir)>;

// Importance sampling of an environment (world directions): sample(u, dir)
// returns the solid-angle density of dir (0: no sample); pdf(dir) is that
// density for any direction.
struct EnvironmentSampler {
    std::function<double(const glm::dvec2& u, glm::dvec3& dir)> sample;
    std::function<double(const glm::dvec3& dir)> pdf;
};

// The radiance a particle of the per_particle micro mode reflects towards
// o (docs/MODELS.md, wang2020; "particle_radiance"): the environment's point
// values (point_values, the default) or L_γ(d), the environment averaged
// over the cone of half-angle γ around the world direction d ("cone"). Stored
// on a lat-long grid (world z polar, φ = atan2(y, x), cell centred) of about
// γ/2 spacing; each texel is the solid-angle weighted mean of the environment
// on a fine lat-long grid (≥ 16 samples across the cone's diameter) over the
// points inside the cone. The GPU uploads data() and reads it with the same
// bilinear lookup (wang2020_tables.glsl wang2020_cone_lookup).
class ParticleRadianceTable {
  public:
    ParticleRadianceTable(const EnvironmentFn& env, double gamma_rad);
    // The point values instead of the cone average ("particle_radiance":
    // "point", the default): texel (x, y) = env at its centre, `rows` rows
    // (the caller takes twice the environment map's, so that the bilinear
    // lookup of the resampled grid stays within half a map texel of the
    // map's own bilinear value). Same lookup, sampling and GPU layout.
    static ParticleRadianceTable point_values(const EnvironmentFn& env, int rows);
    glm::dvec3 lookup(const glm::dvec3& world_dir) const;
    // Importance sampling of L_γ itself (a lat-long EnvironmentMap of the
    // table, luminance-proportional): sample returns the world direction's
    // solid-angle density (0: none), pdf the density of any direction. The
    // effective fraction's moments (PrefilterTable) sample it, since L_γ is
    // non-zero over the sun's disc widened by γ, which the environment's own
    // samples (the disc) would miss.
    double sample(const glm::dvec2& u, glm::dvec3& world_dir) const;
    double pdf(const glm::dvec3& world_dir) const;
    int width() const { return width_; }
    int height() const { return height_; }
    // Texel (x, y) at index y · width + x; rgb = L_γ, w = 0.
    const std::vector<glm::vec4>& data() const { return data_; }

  private:
    ParticleRadianceTable() = default;
    void build_sampling_map();  // map_ from data_
    int width_ = 0, height_ = 0;
    std::vector<glm::vec4> data_;
    std::shared_ptr<const EnvironmentMap> map_;  // for sample() and pdf()
};

struct PrefilterResolution {
    int theta_n = 31, phi_n = 60, theta_o = 10, phi_o = 36;
};
PrefilterResolution default_prefilter_resolution(double alpha);  // Table 2

// M(i, o) of Eq. 11 in the form above without its F (local frame).
double m_term(const glm::dvec3& wi, const glm::dvec3& wo, double alpha);
// F(i·h) of Eq. 11, h = normalize(wi + wo); 1 without a Fresnel (null or
// mode None).
glm::dvec3 m_fresnel(const FresnelDesc* fresnel, const glm::dvec3& wi, const glm::dvec3& wo);

// Orthonormal tangent frame of a world normal (continuous except n = −z).
void tangent_frame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b);
// The azimuth, in the tangent frame of the normal m, of the tangent t of n's
// frame carried to m by the shortest-arc rotation from n to m (the lookup's
// correction of a texel's local azimuth).
double frame_turn(const glm::dvec3& n, const glm::dvec3& t, const glm::dvec3& m);

class PrefilterTable {
  public:
    // dpf: the extracted table for (α, γ); gamma_rad its cone angle.
    // sampler: null selects "as_published" (BRDF samples only), else "mis".
    // fresnel: F of M (null: F = 1).
    // cone: null stores P̂ (Eq. 17) in w; else w holds the effective
    // fraction r(n, o) = E[f]² / E[f²] of one particle's reflected luminance
    // f = lum(L_γ(i) F) M(i, o), m ~ D(m)(m·n), for the per_particle micro
    // scale's "effective" scale selection (wang2020_shading.h), whose
    // estimate's relative variance over a footprint of n particles is
    // 1 / (n r). Same samples as L̂o (MIS weights included).
    PrefilterTable(const DpfTable& dpf, double alpha, double gamma_rad, const EnvironmentFn& env,
                   PrefilterResolution res, int K = 64, const EnvironmentSampler* sampler = nullptr,
                   const FresnelDesc* fresnel = nullptr,
                   const ParticleRadianceTable* cone = nullptr);

    // Quadrilinear lookup: rgb = L̂o(n, o) (Eq. 16), w = P̂(n, o) (Eq. 17)
    // or the effective fraction r(n, o) (built with a cone table).
    glm::dvec4 lookup(const glm::dvec3& n_world, const glm::dvec3& o_world) const;
    // The normal of texel row tn, column pn (cell centres).
    glm::dvec3 texel_normal(int tn, int pn) const;
    // One texel (exact value at the sample directions).
    glm::dvec4 texel(int tn, int pn, int to, int po) const;
    static glm::dvec4 evaluate(const DpfTable& dpf, double alpha, const EnvironmentFn& env,
                               const glm::dvec3& n_world, const glm::dvec3& o_local, int K,
                               uint64_t texel_id = 0, const EnvironmentSampler* sampler = nullptr,
                               const FresnelDesc* fresnel = nullptr,
                               const ParticleRadianceTable* cone = nullptr);

    const PrefilterResolution& resolution() const { return res_; }
    size_t memory_bytes() const { return data_.size() * sizeof(glm::vec4); }
    // The texels, index ((θn · φn + φn) · θo + θo) · φo + φo (the GPU's buffer).
    const std::vector<glm::vec4>& data() const { return data_; }
    double build_seconds() const { return build_seconds_; }

  private:
    PrefilterResolution res_;
    std::vector<glm::vec4> data_;
    double build_seconds_ = 0.0;
};

}  // namespace glintlab::wang2020
