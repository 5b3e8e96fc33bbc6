// Directional probability function (DPF) tables of 001 §3.2 / §4.4.
//
// P(i, o, γ) (Eq. 6) is the probability that a particle, whose normal is drawn
// from the Beckmann density D(h)(h·n), reflects i into the cone of half-angle
// γ around o. For an isotropic NDF it depends on (θi, θo, φo − φi), so it is
// stored in 3-D tables (Table 2: 90 × 90 × 180), one per roughness of the set
// 0.02, 0.04, 0.1, 0.2, 0.4, 0.6, 0.8, 1.0, all with γ = 1° (§4.4 "DPF Buffers
// Generation").
//
// Decision (documented in docs/MODELS.md): Eq. 6 is the Monte-Carlo estimate
// (1/N) Σ 1_Ωh(h_k); we tabulate its N → ∞ limit, the integral of D(m)(m·n)
// over the half-vector region Ωh. That region is the image of the cone of
// reflected directions (solid angle σ(Ωo) = 2π(1 − cos γ)) and has solid angle
// σ(Ωo) / (4 (i·h)) (reflection Jacobian), so
//     P(i, o, γ) = D(h)(h·n) σ(Ωo) / (4 (i·h)),
// evaluated at the cone centre (the relative error of this midpoint rule is
// O(γ²) ≈ 3e-4 for γ = 1°). This removes the Monte-Carlo noise of the table
// (WWH18 count ~10^8 normals per table) at no loss of fidelity.
//
// Extraction (§4.4 "DPF Extraction and Accumulation"): for a roughness α the
// table is interpolated linearly between the two bracketing roughness tables;
// for γ > 1° the 1° table is accumulated over the γ-cone around o (the sum of
// the 1° cells covering the cone, computed by an area-weighted ring quadrature).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace glintlab::wang2020 {

inline constexpr std::array<double, 8> kRoughnessSet = {0.02, 0.04, 0.1, 0.2, 0.4, 0.6, 0.8, 1.0};

struct DpfResolution {
    int theta_i = 90;
    int theta_o = 90;
    int phi = 180;  // φo − φi over [0, 2π)
};

// One 3-D DPF table (θi, θo, Δφ), cell-centred samples, trilinear lookup
// (clamped in θ, periodic in φ).
class DpfTable {
  public:
    DpfTable() = default;
    DpfTable(DpfResolution res, std::vector<float> values);

    // P(i, o) for unit local directions (z = normal); 0 below the horizon.
    double lookup(const glm::dvec3& wi, const glm::dvec3& wo) const;
    double lookup_angles(double theta_i, double theta_o, double dphi) const;

    const DpfResolution& resolution() const { return res_; }
    const std::vector<float>& values() const { return values_; }
    size_t memory_bytes() const { return values_.size() * sizeof(float); }

  private:
    float at(int ti, int to, int p) const;
    DpfResolution res_{};
    std::vector<float> values_;
};

// Analytic DPF (see header comment) for any α, γ; the reference the tables
// are generated from and tested against.
double dpf_exact(const glm::dvec3& wi, const glm::dvec3& wo, double alpha, double gamma_rad);

// Eq. 6 table for one roughness, γ = 1° (or gamma_rad).
DpfTable generate_dpf_table(double alpha, double gamma_rad, DpfResolution res);

// The eight precomputed tables of §4.4 (γ = 1°). Built once per resolution and
// cached (thread-safe).
struct DpfSet {
    DpfResolution res;
    double gamma_rad = 0.0;
    std::array<DpfTable, kRoughnessSet.size()> tables;
    double build_seconds = 0.0;
    size_t memory_bytes() const;
};
const DpfSet& dpf_set(DpfResolution res);
// The set without the in-process memo: read from the on-disk table cache
// (core/disk_cache.h, key: resolution, γ, the roughness set, a table
// version and the glintlab version) or built (with a progress bar on a
// terminal; ~55 s at the default 90 × 90 × 180) and stored there.
DpfSet load_or_build_dpf_set(DpfResolution res);

// The 1° table of the material's roughness: "interpolated" (§4.4, as
// published), linear in α between the two bracketing tables of the set, or
// "exact" (ours, the default), the table of α itself generated as the set's
// are. A linear mix of two Beckmann lobes is not the lobe of the mixed α:
// at α = 0.3 (between 0.2 and 0.4) the mix is +37 % at the specular peak and
// several times too bright in the lobe's tail (docs/MODELS.md wang2020).
enum class DpfRoughness { Exact, Interpolated };

// Extraction: the 1° table of α (above), then γ accumulation of the 1° table
// onto a table for gamma_rad. α must lie in [0.02, 1] and γ in [set γ, 30°]
// (checked: glintlab::Error).
DpfTable extract_dpf(const DpfSet& set, double alpha, double gamma_rad,
                     DpfRoughness roughness = DpfRoughness::Interpolated);
// extract_dpf through the on-disk table cache (key: the set's key, α, γ, the
// roughness mode): the γ accumulation is what takes ~40 s per material at
// 90 × 90 × 180, an exact-α table ~7 s.
DpfTable load_or_extract_dpf(const DpfSet& set, double alpha, double gamma_rad,
                             DpfRoughness roughness = DpfRoughness::Interpolated);

}  // namespace glintlab::wang2020
