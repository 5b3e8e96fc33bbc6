// Spatial quadtree of particle counts (001 §4.4 "Spatial Tree Construction"):
// the N particles of one uv tile [0,1)² are split among the four children of
// each node by a multinomial draw (as in [JHY*14], 002 §3.4), down to a fixed
// depth (11 in the paper, §6).
//
// Compact storage (the paper's two float4 per node — id, count, depth, child
// count, AABB — cost 256 MB, Table 2): only non-empty nodes are stored, 8
// bytes each: the index of the first stored child and the particle count with
// a 4-bit child-occupancy mask. Node id, depth and AABB are implicit in the
// traversal. Particle positions inside a leaf and their random thresholds
// λ(x_k) (Eq. 7) are hashes of (leaf id, particle index), as in WWH18; so
// are the two numbers that draw its normal (per_particle micro mode).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace glintlab::wang2020 {

struct QuadtreeNode {
    uint32_t first_child;  // index into nodes(); children stored contiguously
    uint32_t count_mask;   // bits 0..27: particle count, 28..31: child mask
    uint32_t count() const { return count_mask & 0x0FFFFFFFu; }
    uint32_t mask() const { return count_mask >> 28; }
};

struct Particle {
    glm::dvec2 uv;  // inside the tile [0,1)²
    double lambda;  // λ(x_k) ∈ [0,1), Eq. 7
    // Two unit hashes (4 and 5) that draw the particle's normal from
    // D(m)(m·n) in the per_particle micro mode (wang2020_particle_normal).
    glm::dvec2 normal_u;
};

// Bounds on (particles, depth), checked by the constructor and, with the
// scene file and JSON path, by the scene reader (check_wang2020):
//
// - Particles per leaf, N / 4^depth <= kMaxParticlesPerLeaf. The micro and
//   meso scales count or enumerate the footprint's particles exactly, and a
//   leaf that the footprint's border cuts is resolved particle by particle
//   (count, for_each), so one evaluation costs up to the particles of the
//   few leaves it cuts: at 4096 a cut leaf costs about 0.1 ms (91 us
//   measured for 4063 particles, Release), where depth 1 at 2^28 particles
//   was 6.7e7 particles (seconds) per cut leaf, per evaluation. A smaller
//   bound would need deeper trees (more nodes); at 4096 = 2^28 / 4^8, depth
//   8 and more satisfy it at every density wang2020 accepts, so with the
//   node bound below depths 8..13 are always allowed, the paper's 11 (§6,
//   the default) included.
// - Nodes, Σ_d min(4^d, N) <= kMaxQuadtreeNodes (8 bytes each: 1000 MB).
inline constexpr double kMaxParticlesPerLeaf = 4096.0;
inline constexpr double kMaxQuadtreeNodes = 1.25e8;

// Inline (header-only) so that the scene reader's check, compiled alone in
// the fuzzing build's loaders, needs no quadtree code.
// particles_per_leaf: expected particles per leaf, N / 4^depth.
// quadtree_node_bound: upper bound of the stored nodes, Σ_{d <= depth} min(4^d, N).
// min/max_quadtree_depth: the smallest depth in [1, 16] within
// kMaxParticlesPerLeaf and the largest within kMaxQuadtreeNodes (either may
// be outside [1, 16] when none is: 17 and 0); the allowed depths are [min, max].
inline double particles_per_leaf(uint64_t particles, int depth) {
    return std::ldexp(static_cast<double>(particles), -2 * depth);
}

inline double quadtree_node_bound(uint64_t particles, int depth) {
    double bound = 0.0;
    for (int d = 0; d <= depth; ++d)
        bound += std::min(std::ldexp(1.0, 2 * d), static_cast<double>(particles));
    return bound;
}

inline int min_quadtree_depth(uint64_t particles) {
    int depth = 1;
    while (depth <= 16 && particles_per_leaf(particles, depth) > kMaxParticlesPerLeaf) ++depth;
    return depth;
}

inline int max_quadtree_depth(uint64_t particles) {
    int depth = 16;
    while (depth >= 1 && quadtree_node_bound(particles, depth) > kMaxQuadtreeNodes) --depth;
    return depth;
}

class ParticleQuadtree {
  public:
    // particles ∈ [1, 2^28 − 1], depth ∈ [1, 16] within the bounds above
    // (glintlab::Error otherwise).
    ParticleQuadtree(uint64_t particles, int depth, uint32_t seed);

    uint64_t particles() const { return particles_; }
    int depth() const { return depth_; }
    const std::vector<QuadtreeNode>& nodes() const { return nodes_; }
    size_t memory_bytes() const { return nodes_.size() * sizeof(QuadtreeNode); }
    double build_seconds() const { return build_seconds_; }

    // Σ_k 1_A(x_k) for the axis-aligned uv rectangle A = [lo, hi] (uv may
    // leave the tile: the tile repeats periodically). Exact: leaves cut by the
    // border are resolved particle by particle.
    uint64_t count(glm::dvec2 lo, glm::dvec2 hi) const;
    // Calls fn for every particle inside A (micro-scale traversal, §4.3).
    void for_each(glm::dvec2 lo, glm::dvec2 hi,
                  const std::function<void(const Particle&)>& fn) const;

    // Particle k of the leaf at (x, y) on the finest level.
    Particle leaf_particle(uint32_t x, uint32_t y, uint32_t k) const;

  private:
    template <typename Visit>
    void traverse(glm::dvec2 lo, glm::dvec2 hi, Visit&& visit) const;

    uint64_t particles_;
    int depth_;
    uint32_t seed_;
    std::vector<QuadtreeNode> nodes_;
    double build_seconds_ = 0.0;
};

}  // namespace glintlab::wang2020
