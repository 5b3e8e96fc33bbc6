#include "glintlab/glints/wang2020/wang2020_quadtree.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "glintlab/core/error.h"
#include "glintlab/glints/jakob2014/multinomial.h"

namespace glintlab::wang2020 {

namespace {

uint32_t mix32(uint32_t x) {  // lowbias32 (Wellons)
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

double hash_unit(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    const uint32_t h = mix32(a ^ mix32(b ^ mix32(c ^ mix32(d))));
    return (h >> 8) * 0x1p-24;
}

// Heap-style unique id of node (x, y) at level d.
uint64_t node_id(int d, uint32_t x, uint32_t y) {
    const uint64_t before = ((uint64_t{1} << (2 * d)) - 1) / 3;
    return before + (uint64_t{y} << d) + x;
}

struct Pending {
    uint32_t node;  // index in nodes_
    uint32_t x, y;
};

}  // namespace

ParticleQuadtree::ParticleQuadtree(uint64_t particles, int depth, uint32_t seed)
    : particles_(particles), depth_(depth), seed_(seed) {
    if (particles < 1 || particles > 0x0FFFFFFFu)
        fail("wang2020: particle count {} outside [1, 268435455]", particles);
    if (depth < 1 || depth > 16) fail("wang2020: quadtree depth {} outside [1, 16]", depth);
    const double bound = quadtree_node_bound(particles, depth);
    if (bound > kMaxQuadtreeNodes)
        fail(
            "wang2020: quadtree of {} particles at depth {} may need {:.0f} MB (> 1000 MB); "
            "lower `depth` or the material's log_density",
            particles, depth, bound * 8.0 / 1e6);
    if (particles_per_leaf(particles, depth) > kMaxParticlesPerLeaf)
        fail(
            "wang2020: quadtree of {} particles at depth {} has {:.0f} particles per leaf "
            "(> {:.0f}: a footprint that cuts a leaf enumerates them); use `depth` >= {}",
            particles, depth, particles_per_leaf(particles, depth), kMaxParticlesPerLeaf,
            min_quadtree_depth(particles));
    const auto t0 = std::chrono::steady_clock::now();
    nodes_.push_back({0u, static_cast<uint32_t>(particles)});
    std::vector<Pending> level{{0u, 0u, 0u}}, next;
    const std::array<double, 4> quarter{0.25, 0.25, 0.25, 0.25};
    for (int d = 0; d < depth; ++d) {
        next.clear();
        for (const Pending& p : level) {
            const uint32_t n = nodes_[p.node].count();
            const auto split =
                jakob2014::sample_multinomial4(n, quarter, node_id(d, p.x, p.y), seed_);
            uint32_t mask = 0;
            const auto first = static_cast<uint32_t>(nodes_.size());
            for (uint32_t c = 0; c < 4; ++c) {
                if (split[c] <= 0) continue;
                mask |= 1u << c;
                const uint32_t cx = 2 * p.x + (c & 1u), cy = 2 * p.y + (c >> 1);
                next.push_back({static_cast<uint32_t>(nodes_.size()), cx, cy});
                nodes_.push_back({0u, static_cast<uint32_t>(split[c])});
            }
            nodes_[p.node].first_child = first;
            nodes_[p.node].count_mask = n | (mask << 28);
        }
        std::swap(level, next);
    }
    nodes_.shrink_to_fit();
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Particle ParticleQuadtree::leaf_particle(uint32_t x, uint32_t y, uint32_t k) const {
    const double size = std::ldexp(1.0, -depth_);
    const uint32_t leaf = (y << depth_) + x;
    return {
        {(x + hash_unit(leaf, k, seed_, 1u)) * size, (y + hash_unit(leaf, k, seed_, 2u)) * size},
        hash_unit(leaf, k, seed_, 3u),
        {hash_unit(leaf, k, seed_, 4u), hash_unit(leaf, k, seed_, 5u)}};
}

template <typename Visit>
void ParticleQuadtree::traverse(glm::dvec2 lo, glm::dvec2 hi, Visit&& visit) const {
    if (!(lo.x <= hi.x && lo.y <= hi.y)) return;
    // Periodic tiles overlapped by A, each handled in tile-local coordinates.
    const double tx0 = std::floor(lo.x), tx1 = std::floor(hi.x);
    const double ty0 = std::floor(lo.y), ty1 = std::floor(hi.y);
    if ((tx1 - tx0 + 1) * (ty1 - ty0 + 1) > 64.0)
        fail("wang2020: footprint covers more than 64 tiles; use the macro scale");
    struct Item {
        uint32_t node;
        int d;
        uint32_t x, y;
    };
    std::vector<Item> stack;
    for (double ty = ty0; ty <= ty1; ++ty) {
        for (double tx = tx0; tx <= tx1; ++tx) {
            const glm::dvec2 a{std::max(lo.x - tx, 0.0), std::max(lo.y - ty, 0.0)};
            const glm::dvec2 b{std::min(hi.x - tx, 1.0), std::min(hi.y - ty, 1.0)};
            const glm::dvec2 offset{tx, ty};
            stack.push_back({0u, 0, 0u, 0u});
            while (!stack.empty()) {
                const Item it = stack.back();
                stack.pop_back();
                const QuadtreeNode& node = nodes_[it.node];
                const double size = std::ldexp(1.0, -it.d);
                const glm::dvec2 n0{it.x * size, it.y * size}, n1 = n0 + size;
                if (n1.x <= a.x || n0.x >= b.x || n1.y <= a.y || n0.y >= b.y) continue;
                const bool inside = n0.x >= a.x && n1.x <= b.x && n0.y >= a.y && n1.y <= b.y;
                if (it.d == depth_ || (inside && visit.whole_ok())) {
                    visit.node(*this, it.d, it.x, it.y, node.count(), inside, a, b, offset);
                    if (it.d == depth_ || inside) continue;
                }
                uint32_t child = node.first_child;
                for (uint32_t c = 0; c < 4; ++c) {
                    if (!(node.mask() & (1u << c))) continue;
                    stack.push_back({child++, it.d + 1, 2 * it.x + (c & 1u), 2 * it.y + (c >> 1)});
                }
            }
        }
    }
}

namespace {

struct CountVisit {
    uint64_t total = 0;
    bool whole_ok() const { return true; }
    void node(const ParticleQuadtree& t, int d, uint32_t x, uint32_t y, uint32_t n, bool inside,
              glm::dvec2 a, glm::dvec2 b, glm::dvec2) {
        if (inside) {
            total += n;
            return;
        }
        (void)d;
        for (uint32_t k = 0; k < n; ++k) {
            const Particle p = t.leaf_particle(x, y, k);
            if (p.uv.x >= a.x && p.uv.x < b.x && p.uv.y >= a.y && p.uv.y < b.y) ++total;
        }
    }
};

struct EnumerateVisit {
    const std::function<void(const Particle&)>* fn;
    bool whole_ok() const { return false; }
    void node(const ParticleQuadtree& t, int, uint32_t x, uint32_t y, uint32_t n, bool,
              glm::dvec2 a, glm::dvec2 b, glm::dvec2 offset) {
        for (uint32_t k = 0; k < n; ++k) {
            Particle p = t.leaf_particle(x, y, k);
            if (p.uv.x >= a.x && p.uv.x < b.x && p.uv.y >= a.y && p.uv.y < b.y) {
                p.uv += offset;
                (*fn)(p);
            }
        }
    }
};

}  // namespace

uint64_t ParticleQuadtree::count(glm::dvec2 lo, glm::dvec2 hi) const {
    CountVisit v;
    traverse(lo, hi, v);
    return v.total;
}

void ParticleQuadtree::for_each(glm::dvec2 lo, glm::dvec2 hi,
                                const std::function<void(const Particle&)>& fn) const {
    EnumerateVisit v{&fn};
    traverse(lo, hi, v);
}

}  // namespace glintlab::wang2020
