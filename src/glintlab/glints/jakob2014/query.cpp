#include "glintlab/glints/jakob2014/query.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "glintlab/glints/jakob2014/multinomial.h"
#include "glintlab/glints/jakob2014/tea.h"

namespace glintlab::jakob2014 {
namespace {

constexpr uint64_t kHemisphereId = 1;
constexpr int64_t kLeafParticles = 64;

struct Node {
    UvBox box;
    SphericalTriangle tri;  // unused while tri_id == kHemisphereId
    glm::dvec3 tri_center{0.0, 0.0, 1.0};
    double tri_cap_cos = 0.0;  // cos of the radius of the cap around tri_center
    bool tri_uniform = false;  // D close to uniform over tri (line 12 allowed)
    uint64_t tri_id = kHemisphereId;
    double tri_sigma = 2.0 * std::numbers::pi;
    int64_t count = 0;
    uint64_t id = 1;
    int depth = 0;
    glm::dvec3 area{1.0};  // chromatic: per-channel fraction of all particle area
};

struct Accum {
    double count = 0.0;
    glm::dvec3 area{0.0};
};

// The four children of a direction-tree triangle with their solid angles and
// normalised split probabilities (∫ D(m)(m·n) over each child, Algorithm 2's
// table or its 1-point rule). A pure function of (table, triangle id); the
// top of the tree is shared by all queries, so a small thread-local
// direct-mapped cache avoids recomputing it (same values, bit for bit).
struct DirectionalSplit {
    const NdfIntegralTable* table = nullptr;
    uint64_t id = 0;
    bool valid = false;
    SphericalTriangle child[4];
    glm::dvec3 center[4];
    double cap_cos[4];
    // "D close to uniform within the node" (002 §3.3, before Eq. 10): the
    // triangle needed no composite rule in Algorithm 2, is flat (edges <
    // Model::kMaxFlatEdge, for the planar overlap), and D(m)(m·n) at its
    // vertices is within kUniformTolerance of its value at the centre.
    // Algorithm 2's test alone passes linear gradients (both rules are exact
    // for them), for which the line-12 fraction σ(T ∩ Ω)/σ(T) is biased when
    // the conic sits off the triangle's centre. (A conservative tightening:
    // its effect on the validated means was below their noise.)
    bool uniform[4];
    uint64_t child_id[4];
    double sigma[4];
    std::array<double, 4> p;
};

const DirectionalSplit& directional_split(const NdfIntegralTable& table, uint64_t id,
                                          const SphericalTriangle& t) {
    constexpr size_t kSlots = 1024;
    thread_local std::vector<DirectionalSplit> cache(kSlots);
    DirectionalSplit& d = cache[(id * 0x9e3779b97f4a7c15ull) >> 54];
    if (d.table == &table && d.id == id) return d;
    d.table = &table;
    d.id = id;
    double total = 0.0;
    for (int j = 0; j < 4; ++j) {
        if (id == kHemisphereId) {
            d.child[j] = hemisphere_quadrant(j);
            d.child_id[j] = 2 + uint64_t(j);
        } else {
            d.child[j] = t.child(j);
            d.child_id[j] = child_id(id, j);
        }
        d.sigma[j] = d.child[j].solid_angle();
        d.center[j] = d.child[j].center();
        d.cap_cos[j] = d.child[j].cap_cos(d.center[j]);
        d.uniform[j] = false;
        if (!table.stored(d.child_id[j]) && d.child[j].max_edge_angle() < Model::kMaxFlatEdge) {
            const double dc = table.spec().density(d.center[j]);
            bool u = dc > 0.0;
            for (int i = 0; i < 3 && u; ++i)
                u = std::abs(table.spec().density(d.child[j].v[i]) - dc) <=
                    Model::kUniformTolerance * dc;
            d.uniform[j] = u;
        }
        d.p[j] = std::max(0.0, table.integral(d.child_id[j], d.child[j], d.sigma[j]));
        total += d.p[j];
    }
    d.valid = total > 0.0;
    if (d.valid)
        for (double& v : d.p) v /= total;
    return d;
}

// sample_multinomial4 through a thread-local direct-mapped cache: the top
// levels of the tree (the same node ids, counts and probabilities for every
// query of a material) are drawn once per thread. A pure function of its
// arguments, all of which form the key, so results are bit-identical.
std::array<int64_t, 4> cached_multinomial4(int64_t n, const std::array<double, 4>& p, uint64_t id,
                                           uint32_t seed) {
    if (n <= 8)
        return sample_multinomial4(n, p, id, seed);  // cheap, and the deep levels never repeat
    struct Entry {
        uint64_t id = 0;
        int64_t n = -1;
        uint32_t seed = 0;
        std::array<double, 4> p{};
        std::array<int64_t, 4> k{};
    };
    constexpr size_t kSlots = 4096;
    thread_local std::vector<Entry> cache(kSlots);
    Entry& e = cache[((id ^ (uint64_t(seed) << 32)) * 0x9e3779b97f4a7c15ull) >> 52];
    if (e.id == id && e.n == n && e.seed == seed && e.p == p) return e.k;
    e.id = id;
    e.n = n;
    e.seed = seed;
    e.p = p;
    e.k = sample_multinomial4(n, p, id, seed);
    return e.k;
}

// Pushes the four children of `n` (Eq. 11 decides the split; counts by the
// multinomial of §3.4, seeded by the node id).
void split(const Model& m, const Node& n, std::vector<Node>& queue) {
    Node c[4];
    std::array<double, 4> p{};
    const bool space = split_space(m, n.box.size * n.box.size, n.tri_sigma);
    for (int j = 0; j < 4; ++j) {
        c[j] = n;
        c[j].id = child_id(n.id, j);
        c[j].depth = n.depth + 1;
    }
    if (space) {
        const double h = 0.5 * n.box.size;
        for (int j = 0; j < 4; ++j) {
            c[j].box = {n.box.lo + glm::dvec2((j & 1) * h, (j >> 1) * h), h};
            p[j] = 0.25;
        }
    } else {
        const DirectionalSplit& d = directional_split(*m.table, n.tri_id, n.tri);
        if (!d.valid) return;  // D vanishes on the node: no particles can be here
        for (int j = 0; j < 4; ++j) {
            c[j].tri = d.child[j];
            c[j].tri_id = d.child_id[j];
            c[j].tri_sigma = d.sigma[j];
            c[j].tri_center = d.center[j];
            c[j].tri_cap_cos = d.cap_cos[j];
            c[j].tri_uniform = d.uniform[j];
            p[j] = d.p[j];
        }
    }
    const std::array<int64_t, 4> k = cached_multinomial4(n.count, p, n.id, m.seed);
    if (m.chromatic) {
        for (uint32_t ch = 0; ch < 3; ++ch) {
            const std::array<double, 4> d = sample_dirichlet4(k, n.id, m.seed, ch);
            for (int j = 0; j < 4; ++j) c[j].area[int(ch)] = n.area[int(ch)] * d[j];
        }
    }
    for (int j = 0; j < 4; ++j) {
        if (k[j] == 0) continue;
        c[j].count = k[j];
        queue.push_back(c[j]);
    }
}

// The particles of a leaf at the depth limit, made explicit: the process
// continued to infinite depth places a node's n particles independently,
// uniformly in its uv box and with density D(m)(m·n) in its triangle, so
// drawing them from the node's own TEA stream is the same process (and
// consistent across queries). Directions descend the triangle tree by the
// Algorithm 2 integrals while D is not uniform or the triangle is not flat,
// then are uniform on the (then tiny, flat) triangle.
void count_leaf_particles(const Model& m, const Node& node, const UvParallelogram& q,
                          const SphericalConic& conic, Accum& acc) {
    TeaStream rng(node.id, m.seed, 0x6c656166u /* "leaf" */);
    const double n_total = double(m.particles);
    for (int64_t k = 0; k < node.count; ++k) {
        const glm::dvec2 x =
            node.box.lo + node.box.size * glm::dvec2(rng.next_double(), rng.next_double());
        uint64_t id = node.tri_id;
        SphericalTriangle t = node.tri;
        for (int level = 0; level < 40; ++level) {
            const bool hemi = id == kHemisphereId;
            if (!hemi && !m.table->stored(id) && t.max_edge_angle() < 1e-3) break;
            SphericalTriangle c[4];
            double w[4], total = 0.0;
            for (int j = 0; j < 4; ++j) {
                c[j] = hemi ? hemisphere_quadrant(j) : t.child(j);
                w[j] = std::max(0.0,
                                m.table->integral(hemi ? 2 + uint64_t(j) : child_id(id, j), c[j]));
                total += w[j];
            }
            if (total <= 0.0) break;
            double u = rng.next_double() * total;
            int j = 0;
            while (j < 3 && (u >= w[j] || w[j] <= 0.0)) {
                u -= w[j];
                ++j;
            }
            id = hemi ? 2 + uint64_t(j) : child_id(id, j);
            t = c[j];
        }
        double b1 = rng.next_double(), b2 = rng.next_double();
        if (b1 + b2 > 1.0) {
            b1 = 1.0 - b1;
            b2 = 1.0 - b2;
        }
        const glm::dvec3 dir =
            glm::normalize(t.v[0] + b1 * (t.v[1] - t.v[0]) + b2 * (t.v[2] - t.v[0]));
        if (q.contains(x) && conic.contains(dir)) {
            acc.count += 1.0;
            acc.area += node.area * (n_total / double(node.count));
        }
    }
}

void count_tile(const Model& m, const UvParallelogram& q, const SphericalConic& conic,
                glm::dvec3 conic_wi, glm::dvec3 conic_wo, Accum& acc, QueryStats* stats) {
    thread_local std::vector<Node> queue;
    queue.clear();
    Node root;
    root.box = {glm::dvec2(0.0), 1.0};
    root.count = m.particles;
    if (root.count <= 0) return;
    queue.push_back(root);
    const double eps = m.epsilon;
    const double n_total = double(m.particles);
    size_t head = 0;
    int64_t visited = 0;
    while (head < queue.size()) {
        const Node node = queue[head++];
        ++visited;
        // Line 7: disjoint nodes (empty ones are never pushed).
        const Overlap so = classify_box(q, node.box);
        if (so == Overlap::Disjoint) continue;
        const Overlap dO = node.tri_id == kHemisphereId
                               ? Overlap::Partial
                               : conic.classify(node.tri, node.tri_center, node.tri_cap_cos);
        if (dO == Overlap::Disjoint) continue;
        const double n = double(node.count);
        // Lines 9-10: contained.
        if (so == Overlap::Contained && dO == Overlap::Contained) {
            acc.count += n;
            acc.area += node.area * n_total;
            continue;
        }
        // At the depth limit, a few particles are placed explicitly (exact
        // counts); many take the expected value (line 12) below.
        const bool at_limit = node.depth >= m.max_depth;
        if (at_limit && node.count <= kLeafParticles) {
            count_leaf_particles(m, node, q, conic, acc);
            continue;
        }
        // Lines 11-12: the error criterion (Eq. 10) where D is close to
        // uniform over the node (see DirectionalSplit::uniform).
        const bool uniform = node.tri_id != kHemisphereId && node.tri_uniform;
        // Safeguard (not in the paper): past kNodeBudget visited nodes every
        // partial node takes its expected value, so pathological queries
        // (a conic along the peak of a very narrow D, stored triangles
        // everywhere, 1e13 particles) stay bounded in time and memory.
        const bool over_budget = visited > Model::kNodeBudget;
        if (at_limit || over_budget || (uniform && acc.count > 0.0)) {
            // Fraction of the node's 4-D volume inside the query (line 12).
            auto overlap = [&] {
                const double ps = so == Overlap::Contained ? 1.0
                                                           : box_overlap_area(q, node.box) /
                                                                 (node.box.size * node.box.size);
                if (ps <= 0.0 || dO == Overlap::Contained) return ps;
                // D close to uniform: the planar overlap of §3.3.
                if (node.tri_uniform) return ps * conic.overlap_fraction(node.tri);
                // Otherwise (depth limit or node budget only): the D-weighted
                // fraction ∫_{T∩Ω} D / ∫_T D, with the conic's mass by an
                // 8 x 16 rule over the cone of outgoing directions.
                const bool hemi = node.tri_id == kHemisphereId;
                const double mass = conic_mass(m.table->spec(), conic_wi, conic_wo, m.gamma,
                                               hemi ? nullptr : &node.tri, 8, 16);
                const double total =
                    hemi ? 1.0 : m.table->integral(node.tri_id, node.tri, node.tri_sigma);
                return total > 0.0 ? ps * std::min(1.0, mass / total) : 0.0;
            };
            const double bound = eps * acc.count;
            // max_p n p (1 - p) = n / 4: skip the overlap when Eq. 10 holds for any p.
            bool ok = at_limit || over_budget || 0.25 * n < bound * bound;
            double p = -1.0;
            if (!ok) {
                p = overlap();
                ok = n * p * (1.0 - p) < bound * bound;
            }
            if (ok) {
                if (p < 0.0) p = overlap();
                acc.count += n * p;
                acc.area += node.area * (n_total * p);
                continue;
            }
        }
        // Lines 13-15.
        split(m, node, queue);
    }
    if (stats) {
        stats->nodes += visited;
        stats->max_queue = std::max<int64_t>(stats->max_queue, int64_t(queue.size()));
        if (visited > Model::kNodeBudget) ++stats->over_budget;
    }
}

}  // namespace

QueryResult query_count(const Model& m, const UvParallelogram& q_in, glm::dvec3 wi, glm::dvec3 wo,
                        QueryStats* stats) {
    QueryResult r;
    if (stats) ++stats->queries;
    const SphericalConic conic = SphericalConic::make(wi, wo, m.gamma);
    // Move the footprint's centre into the unit tile, then visit every tile
    // its bounding box touches.
    UvParallelogram q = q_in;
    q.center -= glm::floor(q.center);
    q.prepare();
    const glm::dvec2 half = 0.5 * (glm::abs(q.e1) + glm::abs(q.e2));
    const glm::dvec2 lo = glm::floor(q.center - half), hi = glm::floor(q.center + half);
    const double tiles = (hi.x - lo.x + 1.0) * (hi.y - lo.y + 1.0);
    Accum acc;
    if (tiles > kMaxTiles) {
        const double f = expected_fraction(m.table->spec(), q.area(), wi, wo, m.gamma);
        acc.count = f * double(m.particles);
        acc.area = glm::dvec3(acc.count);
    } else {
        for (double ty = lo.y; ty <= hi.y; ty += 1.0)
            for (double tx = lo.x; tx <= hi.x; tx += 1.0) {
                UvParallelogram qt = q;
                qt.center -= glm::dvec2(tx, ty);
                count_tile(m, qt, conic, wi, wo, acc, stats);
            }
    }
    r.count = acc.count;
    r.area = m.chromatic ? acc.area : glm::dvec3(acc.count);
    if (stats) stats->particles += acc.count;
    return r;
}

double conic_mass(const NdfSpec& spec, glm::dvec3 wi, glm::dvec3 wo, double gamma,
                  const SphericalTriangle* t, int rings, int sectors) {
    wi = glm::normalize(wi);
    wo = glm::normalize(wo);
    // Frame around wo.
    const glm::dvec3 t0 = std::abs(wo.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 tx = glm::normalize(glm::cross(wo, t0)), ty = glm::cross(wo, tx);
    const double cos_g = std::cos(gamma);
    double sum = 0.0;
    for (int i = 0; i < rings; ++i) {
        // Uniform in cos θ: dω = d(cos θ) dφ.
        const double ct = 1.0 - (i + 0.5) / rings * (1.0 - cos_g);
        const double st = std::sqrt(std::max(0.0, 1.0 - ct * ct));
        for (int j = 0; j < sectors; ++j) {
            const double phi = (j + 0.5) / sectors * 2.0 * std::numbers::pi;
            const glm::dvec3 o = ct * wo + st * (std::cos(phi) * tx + std::sin(phi) * ty);
            const glm::dvec3 hsum = wi + o;
            if (glm::dot(hsum, hsum) <= 0.0) continue;
            const glm::dvec3 mm = glm::normalize(hsum);
            const double wim = glm::dot(wi, mm);
            if (wim <= 0.0 || (t && !t->contains(mm))) continue;
            sum += spec.density(mm) / (4.0 * wim);
        }
    }
    return sum * (1.0 - cos_g) * 2.0 * std::numbers::pi / (double(rings) * sectors);
}

double expected_fraction(const NdfSpec& spec, double area, glm::dvec3 wi, glm::dvec3 wo,
                         double gamma) {
    return area * conic_mass(spec, wi, wo, gamma, nullptr, 64, 128);
}

}  // namespace glintlab::jakob2014
