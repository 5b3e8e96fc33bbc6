#include "glintlab/glints/jakob2014/uv_overlap.h"

#include <algorithm>
#include <cmath>

namespace glintlab::jakob2014 {
namespace {

double cross2(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

// Parallelogram coordinates (a, b) of point x.
glm::dvec2 local(const UvParallelogram& q, glm::dvec2 x) {
    const glm::dvec2 d = x - q.center;
    return {glm::dot(q.inv_row0, d), glm::dot(q.inv_row1, d)};
}

}  // namespace

void UvParallelogram::prepare() {
    const double det = cross2(e1, e2);
    inv_row0 = glm::dvec2(e2.y, -e2.x) / det;
    inv_row1 = glm::dvec2(-e1.y, e1.x) / det;
    half = 0.5 * (glm::abs(e1) + glm::abs(e2));
    n1 = {-e1.y, e1.x};
    n2 = {-e2.y, e2.x};
    r1 = 0.5 * std::abs(glm::dot(n1, e2));
    r2 = 0.5 * std::abs(glm::dot(n2, e1));
}

bool UvParallelogram::contains(glm::dvec2 x) const {
    const glm::dvec2 l = local(*this, x);
    return std::abs(l.x) <= 0.5 && std::abs(l.y) <= 0.5;
}

Overlap classify_box(const UvParallelogram& q, const UvBox& b) {
    // Separating axes: the box's (x, y) first (cheap), then the
    // parallelogram's edge normals.
    const glm::dvec2 hi = b.lo + glm::dvec2(b.size);
    if (q.center.x - q.half.x > hi.x || q.center.x + q.half.x < b.lo.x) return Overlap::Disjoint;
    if (q.center.y - q.half.y > hi.y || q.center.y + q.half.y < b.lo.y) return Overlap::Disjoint;
    const glm::dvec2 corners[4] = {b.lo, {hi.x, b.lo.y}, hi, {b.lo.x, hi.y}};
    const glm::dvec2 ns[2] = {q.n1, q.n2};
    const double rs[2] = {q.r1, q.r2};
    for (int k = 0; k < 2; ++k) {
        // The parallelogram spans ±r_k around n_k·center along n_k (the
        // edge e_k itself has no extent along its own normal).
        const double c = glm::dot(ns[k], q.center);
        double lo = 1e300, hv = -1e300;
        for (const glm::dvec2& p : corners) {
            const double v = glm::dot(ns[k], p);
            lo = std::min(lo, v);
            hv = std::max(hv, v);
        }
        if (lo > c + rs[k] || hv < c - rs[k]) return Overlap::Disjoint;
    }
    // Containment: every box corner inside the parallelogram.
    for (const glm::dvec2& c : corners) {
        const glm::dvec2 l = local(q, c);
        if (std::abs(l.x) > 0.5 || std::abs(l.y) > 0.5) return Overlap::Partial;
    }
    return Overlap::Contained;
}

double box_overlap_area(const UvParallelogram& q, const UvBox& b) {
    // Clip the parallelogram (CCW) by the box's four half-planes.
    glm::dvec2 poly[16], next[16];
    int n = 4;
    glm::dvec2 e1 = q.e1, e2 = q.e2;
    if (cross2(e1, e2) < 0.0) std::swap(e1, e2);
    poly[0] = q.center - 0.5 * e1 - 0.5 * e2;
    poly[1] = q.center + 0.5 * e1 - 0.5 * e2;
    poly[2] = q.center + 0.5 * e1 + 0.5 * e2;
    poly[3] = q.center - 0.5 * e1 + 0.5 * e2;
    const double hi_x = b.lo.x + b.size, hi_y = b.lo.y + b.size;
    for (int side = 0; side < 4 && n > 0; ++side) {
        auto inside = [&](glm::dvec2 p) {
            switch (side) {
                case 0:
                    return p.x >= b.lo.x;
                case 1:
                    return p.x <= hi_x;
                case 2:
                    return p.y >= b.lo.y;
                default:
                    return p.y <= hi_y;
            }
        };
        auto cut = [&](glm::dvec2 p, glm::dvec2 r) {
            double t;
            switch (side) {
                case 0:
                    t = (b.lo.x - p.x) / (r.x - p.x);
                    break;
                case 1:
                    t = (hi_x - p.x) / (r.x - p.x);
                    break;
                case 2:
                    t = (b.lo.y - p.y) / (r.y - p.y);
                    break;
                default:
                    t = (hi_y - p.y) / (r.y - p.y);
                    break;
            }
            return p + t * (r - p);
        };
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 p = poly[i], r = poly[(i + 1) % n];
            const bool pin = inside(p), rin = inside(r);
            if (pin) next[m++] = p;
            if (pin != rin) next[m++] = cut(p, r);
        }
        n = m;
        std::copy(next, next + n, poly);
    }
    double area = 0.0;
    for (int i = 0; i < n; ++i) area += cross2(poly[i], poly[(i + 1) % n]);
    return std::max(0.0, 0.5 * area);
}

}  // namespace glintlab::jakob2014
