// Algorithm 1 of 002: the breadth-first hierarchical count of particles in the
// 4-D query A × Ω_h over the implicit tree of (uv box × spherical triangle)
// nodes whose counts are generated top-down by the stochastic process of §3.4.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "glintlab/glints/jakob2014/ndf_integral.h"
#include "glintlab/glints/jakob2014/uv_overlap.h"

namespace glintlab::jakob2014 {

// Everything a query needs, fixed per material.
struct Model {
    const NdfIntegralTable* table = nullptr;
    int64_t particles = 0;  // N: particles in the unit uv square (one texture tile)
    double gamma = 0.0;     // cone radius (radians)
    double epsilon = 0.1;   // Eq. 10
    int max_depth = 20;
    uint32_t seed = 0;
    bool chromatic = false;
    // Eq. 11 statistics: expected uv area and solid angle of a query.
    double query_area = 1e-6;
    double query_solid_angle = 1e-4;
    // Triangles wider than this are never approximated by line 12 (the
    // planar overlap needs nearly flat triangles, §3.3).
    static constexpr double kMaxFlatEdge = 0.2;
    // Largest relative deviation of D(m)(m·n) between a triangle's vertices
    // and its centre for line 12 to treat D as uniform over the triangle.
    static constexpr double kUniformTolerance = 0.02;
    // Nodes one tile's traversal may visit before every partial node takes
    // its expected value (a safeguard; counted in docs/VALIDATION.md).
    static constexpr int64_t kNodeBudget = 20000;
};

struct QueryStats {
    int64_t queries = 0;
    int64_t nodes = 0;       // nodes popped from the queue (002 Table 1 "nodes")
    double particles = 0.0;  // particles found (Table 1 "count")
    int64_t max_queue = 0;
    int64_t over_budget = 0;  // tile traversals that hit Model::kNodeBudget
};

struct QueryResult {
    double count = 0.0;  // particles in A × Ω_h (fractional where line 12 applied)
    glm::dvec3 area{0.0};  // chromatic: per channel, Σ particle areas × N (§3.5); = count otherwise
};

// Counts particles of the unit-periodic texture in q × Ω_h(wi, wo, γ). The
// parallelogram may straddle tile borders: it is split at integer uv lines
// and each tile's part is counted in the same (periodic) tree. Footprints
// covering more than kMaxTiles tiles return the expected count (smooth limit).
constexpr int kMaxTiles = 64;
QueryResult query_count(const Model& model, const UvParallelogram& q, glm::dvec3 wi, glm::dvec3 wo,
                        QueryStats* stats);

// Node ids (002 §3.4): the root is 1, child j in 0..3 of node i is 4i + j - 2.
inline uint64_t child_id(uint64_t i, int j) {
    return 4u * i + uint64_t(j) - 2u;
}
inline uint64_t parent_id(uint64_t id) {
    return (id + 2u) / 4u;
}

// Split rule of Eq. 11: true = split the node in space.
inline bool split_space(const Model& m, double node_area, double node_solid_angle) {
    return m.query_area / node_area < m.query_solid_angle / node_solid_angle;
}

// Exact expected fraction of the N particles in A × Ω_h for a footprint of
// uv area `area`: area · ∫_{Ω_h} D(m)(m·n) dm, integrated over the cone of
// outgoing directions (dm = dωo / (4 ωi·m)) by a fine midpoint rule.
double expected_fraction(const NdfSpec& spec, double area, glm::dvec3 wi, glm::dvec3 wo,
                         double gamma);
// ∫_{Ω_h ∩ T} D(m)(m·n) dm (T = null: the whole of Ω_h) by a rings × sectors
// midpoint rule over the cone of outgoing directions.
double conic_mass(const NdfSpec& spec, glm::dvec3 wi, glm::dvec3 wo, double gamma,
                  const SphericalTriangle* t, int rings, int sectors);

}  // namespace glintlab::jakob2014
