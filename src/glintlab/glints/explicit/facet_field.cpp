// The procedural facet field of explicit.h: quadtree of exact binomial
// splits, leaves of uniform facets (explicit.h header comment).
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>

#include "glintlab/core/error.h"
#include "glintlab/core/glsl.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/explicit/binomial_half.h"
#include "glintlab/glints/explicit/explicit.h"
#include "glintlab/glints/glint_textures.h"

// visible_slope: each facet's map normal faces the pixel's wo as the models'
// mean normal does (render/surface_bsdf.cpp).
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/core/slope_frame.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

// Mean facets per leaf the depth aims at (a leaf holds 8-32 on average):
// fewer makes the descent dominate, more makes leaves cut by the footprint
// boundary generate facets outside it.
constexpr double kLeafTarget = 32.0;
constexpr int kMaxDepth = 24;
constexpr double kMaxLogDensity = 30.0;  // N <= 1.07e13
// Footprints that touch more tiles than this are rejected (each touched
// tile costs a quadtree descent). Only the tiles the parallelogram touches
// count, not its bounding box: a thin footprint along a silhouette
// (257 x 113 tiles of bounding box at ln density 7-8 on the compare scenes)
// touches a few hundred.
constexpr double kMaxTiles = 4096.0;

// Stream salts: split draws and leaf contents use independent streams.
constexpr uint64_t kSplitSalt = 0x5bd1e9955bd1e995ULL;
constexpr uint64_t kLeafSalt = 0xc2b2ae3d27d4eb4fULL;
constexpr uint64_t kThinSalt = 0x165667b19e3779f9ULL;

// Unique id of quadtree node (depth, ix, iy): ix, iy < 2^24.
uint64_t node_key(int depth, uint32_t ix, uint32_t iy) {
    return (static_cast<uint64_t>(depth) << 48) ^ (static_cast<uint64_t>(ix) << 24) ^
           static_cast<uint64_t>(iy);
}

Pcg32 node_stream(uint64_t key, uint32_t seed, uint64_t salt) {
    const uint64_t s = mix_bits(static_cast<uint64_t>(seed) ^ salt);
    return Pcg32(mix_bits(key ^ s), mix_bits(key + s));
}

// The footprint parallelogram in one tile's coordinates, prepared for the
// containment test (s, t coordinates) and the separating-axis test.
struct Parallelogram {
    glm::dvec2 c{0.0}, e1{0.0}, e2{0.0};
    glm::dvec2 inv0{0.0}, inv1{0.0};  // rows of (e1 e2)^-1
    glm::dvec2 half{0.0};             // half extents of the bounding box
    glm::dvec2 n1{0.0}, n2{0.0};      // edge normals (n1 ⊥ e1, n2 ⊥ e2)
    double r1 = 0.0, r2 = 0.0;        // half widths along n1, n2

    bool prepare(glm::dvec2 center, glm::dvec2 a, glm::dvec2 b) {
        c = center, e1 = a, e2 = b;
        const double det = e1.x * e2.y - e1.y * e2.x;
        if (det == 0.0 || !std::isfinite(det)) return false;
        inv0 = glm::dvec2(e2.y, -e2.x) / det;
        inv1 = glm::dvec2(-e1.y, e1.x) / det;
        half = 0.5 * (glm::abs(e1) + glm::abs(e2));
        n1 = glm::dvec2(-e1.y, e1.x);
        n2 = glm::dvec2(-e2.y, e2.x);
        r1 = 0.5 * std::abs(glm::dot(e2, n1));
        r2 = 0.5 * std::abs(glm::dot(e1, n2));
        return true;
    }
    // s, t in [-1/2, 1/2).
    bool contains(glm::dvec2 p) const {
        const glm::dvec2 d = p - c;
        const double s = glm::dot(inv0, d), t = glm::dot(inv1, d);
        return s >= -0.5 && s < 0.5 && t >= -0.5 && t < 0.5;
    }
    // Separating-axis test against the box [lo, lo + size]² (conservative:
    // touching counts as overlapping).
    bool overlaps(glm::dvec2 lo, double size) const {
        const double h = 0.5 * size;
        const glm::dvec2 bc = lo + h;
        const glm::dvec2 d = c - bc;
        if (std::abs(d.x) > half.x + h || std::abs(d.y) > half.y + h) return false;
        if (std::abs(glm::dot(d, n1)) > r1 + h * (std::abs(n1.x) + std::abs(n1.y))) return false;
        if (std::abs(glm::dot(d, n2)) > r2 + h * (std::abs(n2.x) + std::abs(n2.y))) return false;
        return true;
    }
};

// [xmin, xmax] of the parallelogram's points with y in [a, b] (closed, so
// conservative); xmin > xmax when it misses the band. It is convex: the
// extremes lie at its vertices inside the band or where its edges cross
// y = a or y = b.
glm::dvec2 band_x_range(const Parallelogram& q, double a, double b) {
    const glm::dvec2 v[4] = {q.c - 0.5 * q.e1 - 0.5 * q.e2, q.c + 0.5 * q.e1 - 0.5 * q.e2,
                             q.c + 0.5 * q.e1 + 0.5 * q.e2, q.c - 0.5 * q.e1 + 0.5 * q.e2};
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec2 p = v[i], r = v[(i + 1) % 4];
        if (p.y >= a && p.y <= b) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
        for (const double y : {a, b})
            if ((p.y - y) * (r.y - y) <= 0.0 && p.y != r.y) {
                const double x = p.x + (y - p.y) * (r.x - p.x) / (r.y - p.y);
                lo = std::min(lo, x), hi = std::max(hi, x);
            }
    }
    return glm::dvec2(lo, hi);
}

struct Walker {
    const ExplicitFacetField& field;
    const Parallelogram& q;
    glm::dvec2 tile;  // offset added to reported positions
    int depth;
    const std::function<void(const ExplicitFacet&)>& visit;
    double n_field = 0.0;  // facets per tile (the density map's thinning)
    uint64_t visited = 0;

    void node(int level, uint32_t ix, uint32_t iy, int64_t n) {
        if (n == 0) return;
        const double size = std::ldexp(1.0, -level);
        if (!q.overlaps(glm::dvec2(ix, iy) * size, size)) return;
        if (level == depth) return leaf(ix, iy, n, size);
        // Two levels of halving: u first, then v in each half (the 4-way
        // multinomial with equal probabilities 1/4, drawn exactly).
        Pcg32 rng = node_stream(node_key(level, ix, iy), field.seed, kSplitSalt);
        const int64_t left = explicit_gt::sample_binomial_half(n, rng);
        const int64_t right = n - left;
        const int64_t left_lo = explicit_gt::sample_binomial_half(left, rng);
        const int64_t right_lo = explicit_gt::sample_binomial_half(right, rng);
        const uint32_t cx = 2 * ix, cy = 2 * iy;
        node(level + 1, cx, cy, left_lo);
        node(level + 1, cx, cy + 1, left - left_lo);
        node(level + 1, cx + 1, cy, right_lo);
        node(level + 1, cx + 1, cy + 1, right - right_lo);
    }

    void leaf(uint32_t ix, uint32_t iy, int64_t n, double size) {
        Pcg32 rng = node_stream(node_key(depth, ix, iy), field.seed, kLeafSalt);
        for (int64_t k = 0; k < n; ++k) {
            // Four draws per facet whether or not it is inside, so a facet
            // never depends on the footprint that enumerates it.
            const double u = (ix + rng.next_double()) * size;
            const double v = (iy + rng.next_double()) * size;
            const double u1 = rng.next_double(), u2 = rng.next_double();
            const glm::dvec2 p(u, v);
            if (!q.contains(p)) continue;
            ExplicitFacet f;
            f.uv = glm::vec2(p + tile);
            float ax = field.alpha_x, ay = field.alpha_y;
            if (const GlintTextures* t = field.textures) {
                if (t->density) {
                    const double density = double(t->density->at(f.uv).x);
                    const uint64_t h =
                        mix_bits(node_key(depth, ix, iy) ^
                                 mix_bits(uint64_t(k) ^ (uint64_t(field.seed) << 32) ^ kThinSalt));
                    const double keep = double(h >> 11) * 0x1.0p-53;
                    if (!(keep * n_field < density)) continue;
                    f.weight = float(n_field / density);
                }
                if (t->alpha_x_sq) ax = alpha_from_squared(t->alpha_x_sq->at(f.uv).x);
                if (t->alpha_y_sq && t->alpha_y_sq == t->alpha_x_sq)  // an isotropic map
                    ay = ax;
                else if (t->alpha_y_sq)
                    ay = alpha_from_squared(t->alpha_y_sq->at(f.uv).x);
            }
            f.m = sample_explicit_normal(field.ndf, ax, ay, u1, u2);
            if (field.has_macro_normals()) {
                glm::vec2 slope = field.slope_gradient * (f.uv - field.slope_origin);
                if (field.normal_map)
                    slope += shader::visible_slope(
                        field.normal_map->slope_at(f.uv) * field.normal_map_axes,
                        field.normal_map_view);
                f.n_map = normal_from_slope(slope);
                glm::vec3 b;
                tangent_frame_around(f.n_map, &f.t_map, &b);
                f.m = glm::normalize(f.m.x * f.t_map + f.m.y * b + f.m.z * f.n_map);
            }
            visit(f);
            ++visited;
        }
    }
};

}  // namespace

void validate_explicit_field(const ExplicitFacetField& field) {
    if (!(field.log_density >= 0.0 && field.log_density <= kMaxLogDensity))
        fail(
            "explicit: log_density = {} is out of range [0, {}] (N = e^log_density facets per "
            "unit uv area must stay an exact count below 1.07e13)",
            field.log_density, kMaxLogDensity);
    const auto bad_alpha = [](float a) { return !(a >= 1e-4f && a <= 4.0f); };
    if (bad_alpha(field.alpha_x) || bad_alpha(field.alpha_y))
        fail("explicit: roughness (alpha_x, alpha_y) = ({}, {}) is out of range [1e-4, 4]",
             field.alpha_x, field.alpha_y);
    if (!(field.max_facets_per_footprint >= 1.0))
        fail("explicit: max_facets_per_footprint = {} must be >= 1",
             field.max_facets_per_footprint);
}

uint64_t explicit_facets_per_tile(const ExplicitFacetField& field) {
    return static_cast<uint64_t>(std::llround(std::exp(field.log_density)));
}

int explicit_leaf_depth(const ExplicitFacetField& field) {
    const double n = static_cast<double>(explicit_facets_per_tile(field));
    int depth = 0;
    while (depth < kMaxDepth && n / std::ldexp(1.0, 2 * depth) > kLeafTarget) ++depth;
    return depth;
}

double explicit_footprint_area(const Footprint& fp) {
    return std::abs(double(fp.duvdx.x) * fp.duvdy.y - double(fp.duvdx.y) * fp.duvdy.x);
}

glm::vec3 sample_explicit_normal(NdfType ndf, float alpha_x, float alpha_y, double u1, double u2) {
    // Radius in the stretched slope space (alpha = 1), inverse radial CDF:
    // Beckmann P22 = e^{-r²}/π → r² = -ln(1 - u1); GGX P22 = 1/(π(1 + r²)²)
    // → r² = u1 / (1 - u1).
    const double r2 = ndf == NdfType::Beckmann ? -std::log1p(-u1) : u1 / (1.0 - u1);
    const double r = std::sqrt(r2);
    const double phi = 2.0 * std::numbers::pi * u2;
    const double sx = alpha_x * r * std::cos(phi), sy = alpha_y * r * std::sin(phi);
    // Slopes (sx, sy) = (-m.x/m.z, -m.y/m.z) (Heitz 2014 Eq. 36).
    const double inv = 1.0 / std::sqrt(sx * sx + sy * sy + 1.0);
    return glm::vec3(float(-sx * inv), float(-sy * inv), float(inv));
}

Footprint explicit_enumerated_footprint(const ExplicitFacetField& field, const Footprint& fp) {
    if (!field.subsample_over_budget) return fp;
    const double expected = double(explicit_facets_per_tile(field)) * explicit_footprint_area(fp);
    if (!(expected > field.max_facets_per_footprint) || !std::isfinite(expected)) return fp;
    const double k_real = std::ceil(std::sqrt(expected / field.max_facets_per_footprint));
    if (!(k_real <= 65536.0)) return fp;  // beyond any image: for_each names the footprint
    const uint32_t k = static_cast<uint32_t>(k_real);
    const uint64_t key = mix_bits((uint64_t(std::bit_cast<uint32_t>(fp.uv.x)) << 32) ^
                                  std::bit_cast<uint32_t>(fp.uv.y) ^ (uint64_t(field.seed) << 17));
    const uint32_t cell = static_cast<uint32_t>(key % (uint64_t(k) * k));
    const float i = float(cell % k), j = float(cell / k), kf = float(k);
    Footprint part = fp;
    part.duvdx = fp.duvdx / kf;
    part.duvdy = fp.duvdy / kf;
    part.uv = fp.uv + ((i + 0.5f) / kf - 0.5f) * fp.duvdx + ((j + 0.5f) / kf - 0.5f) * fp.duvdy;
    return part;
}

uint64_t for_each_explicit_facet(const ExplicitFacetField& field, const Footprint& fp,
                                 const std::function<void(const ExplicitFacet&)>& visit) {
    validate_explicit_field(field);
    const glm::dvec2 c(fp.uv), e1(fp.duvdx), e2(fp.duvdy);
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(e1.x) ||
        !std::isfinite(e1.y) || !std::isfinite(e2.x) || !std::isfinite(e2.y))
        fail(
            "explicit: the pixel footprint is not finite (uv = ({}, {}), duvdx = ({}, {}), "
            "duvdy = ({}, {}))",
            c.x, c.y, e1.x, e1.y, e2.x, e2.y);
    const uint64_t n = explicit_facets_per_tile(field);
    const double area = explicit_footprint_area(fp);
    const double expected = double(n) * area;
    if (expected > field.max_facets_per_footprint)
        fail(
            "explicit: the pixel footprint (|duvdx| = {:.3g}, |duvdy| = {:.3g}, area {:.3g} uv²) "
            "holds {:.3g} facets in expectation at log_density {} ({:.3g} facets per unit uv "
            "area), more than max_facets_per_footprint = {:.3g}; lower log_density, raise the "
            "resolution or raise max_facets_per_footprint",
            glm::length(e1), glm::length(e2), area, expected, field.log_density, double(n),
            field.max_facets_per_footprint);
    Parallelogram q;
    if (!q.prepare(c, e1, e2) || n == 0) return 0;
    const glm::dvec2 lo = c - q.half, hi = c + q.half;
    // Tiles are walked one integer step at a time: beyond 2^53 a step of 1
    // does not change a double (the walk looped forever at uv ~1e16), and
    // far below that a tile's facets lose their sub-tile precision.
    constexpr double kMaxTileCoordinate = 1e9;
    if (!(std::max({std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)}) <
          kMaxTileCoordinate))
        fail(
            "explicit: the pixel footprint around uv = ({:.6g}, {:.6g}) reaches beyond the facet "
            "field's range: |u| and |v| must stay below {:.0e}",
            c.x, c.y, kMaxTileCoordinate);
    const double x0 = std::floor(lo.x), x1 = std::floor(hi.x);
    const double y0 = std::floor(lo.y), y1 = std::floor(hi.y);
    // The tiles each row of tiles [ty, ty + 1] needs: those the
    // parallelogram's x-range over the row touches, widened by a rounding
    // margin (a tile walked in vain finds no facet: the sums are those of
    // walking the whole bounding box, in the same order).
    auto row_tiles = [&](double ty) {
        const glm::dvec2 r = band_x_range(q, ty, ty + 1.0);
        if (!(r.x <= r.y)) return glm::dvec2(1.0, 0.0);
        const double margin = 1e-9 * (1.0 + std::abs(r.x) + std::abs(r.y));
        return glm::dvec2(std::max(x0, std::floor(r.x - margin)),
                          std::min(x1, std::floor(r.y + margin)));
    };
    // Every row of the bounding box touches at least one tile (the
    // parallelogram is connected), so more rows than kMaxTiles fail at once.
    double touched = y1 - y0 + 1.0;
    if (touched <= kMaxTiles) {
        touched = 0.0;
        for (double ty = y0; ty <= y1; ty += 1.0) {
            const glm::dvec2 r = row_tiles(ty);
            touched += std::max(0.0, r.y - r.x + 1.0);
        }
    }
    if (touched > kMaxTiles)
        fail(
            "explicit: the pixel footprint touches {} uv tiles (more than {}; its bounding box "
            "spans {} x {} tiles)",
            touched, kMaxTiles, x1 - x0 + 1.0, y1 - y0 + 1.0);
    const int depth = explicit_leaf_depth(field);
    uint64_t visited = 0;
    for (double ty = y0; ty <= y1; ty += 1.0) {
        const glm::dvec2 r = row_tiles(ty);
        for (double tx = r.x; tx <= r.y; tx += 1.0) {
            const glm::dvec2 tile(tx, ty);
            Parallelogram local = q;
            local.c = c - tile;
            Walker w{field, local, tile, depth, visit, double(n)};
            w.node(0, 0, 0, static_cast<int64_t>(n));
            visited += w.visited;
        }
    }
    return visited;
}

}  // namespace glintlab
