// Integrals of the smooth microfacet distribution over spherical triangles of
// the direction tree (002 §3.4, Algorithm 2), memoised in a hash table keyed
// by the triangle's id (hemisphere 1, quadrant j of the hemisphere 2 + j,
// child j of triangle i: 4i + j - 2).
//
// What is integrated: the particles' normals are distributed with density
// D(m)(m·n), the projected-area normal distribution (∫_H² D(m)(m·n) dm = 1);
// see MODELS.md, "decisions". The table is built once per (NDF, αx, αy)
// before rendering (Algorithm 2 on the four quadrants, δabs = δrel = 1e-5)
// and is read-only afterwards, so lookups need no lock and every thread sees
// the same values (deterministic images for any thread count).
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>

#include "glintlab/glints/jakob2014/spherical_geometry.h"

namespace glintlab::jakob2014 {

struct NdfSpec {
    int ndf = 0;  // shader::NDF_BECKMANN or shader::NDF_GGX
    float alpha_x = 0.3f, alpha_y = 0.3f;
    float rho = 0.0f;  // the slopes' correlation (a sheared lobe, GlintDesc::slope_correlation)
    bool operator==(const NdfSpec&) const = default;
    // D(m)(m·n), the density of particle normals.
    double density(glm::dvec3 m) const;
};

class NdfIntegralTable {
  public:
    static constexpr double kDelta = 1e-5;  // δabs = δrel (002 §3.4)
    static constexpr int kMaxDepth = 22;    // recursion cap below a quadrant (ids < 2^50)

    explicit NdfIntegralTable(const NdfSpec& spec);

    // ∫_T D(m)(m·n) dm: the stored entry, else the 1-point rule σ(T) D(centre) (Algorithm 2 text).
    double integral(uint64_t id, const SphericalTriangle& t) const {
        return integral(id, t, t.solid_angle());
    }
    // The same with σ(T) known.
    double integral(uint64_t id, const SphericalTriangle& t, double solid_angle) const;
    // Whether T needed a composite rule (D is not close to uniform over T).
    bool stored(uint64_t id) const { return table_.count(id) != 0; }
    const NdfSpec& spec() const { return spec_; }
    size_t entries() const { return table_.size(); }
    // Approximate heap footprint of the hash table (buckets + nodes).
    size_t memory_bytes() const;

  private:
    double integrate(uint64_t id, const SphericalTriangle& t, int depth);

    NdfSpec spec_;
    std::unordered_map<uint64_t, double> table_;
};

// The shared table of an NDF, built on first use (thread-safe: a registry
// guarded by a mutex, with a thread-local last-hit cache so the hot path
// takes no lock; a built table is immutable). Tables live until exit.
const NdfIntegralTable& ndf_integral_table(const NdfSpec& spec);

// Sum of memory_bytes() over all tables built so far (for benchmarks).
size_t ndf_integral_tables_memory_bytes();

}  // namespace glintlab::jakob2014
