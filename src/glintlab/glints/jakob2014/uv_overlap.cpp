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
    const double det = cross2(q.e1, q.e2);
    const glm::dvec2 d = x - q.center;
    return {cross2(d, q.e2) / det, cross2(q.e1, d) / det};
}

}  // namespace

bool UvParallelogram::contains(glm::dvec2 x) const {
    const glm::dvec2 l = local(*this, x);
    return std::abs(l.x) <= 0.5 && std::abs(l.y) <= 0.5;
}

Overlap classify_box(const UvParallelogram& q, const UvBox& b) {
    const glm::dvec2 corners[4] = {b.lo, b.lo + glm::dvec2(b.size, 0), b.lo + glm::dvec2(b.size),
                                   b.lo + glm::dvec2(0, b.size)};
    // Containment: every box corner inside the parallelogram.
    bool all_in = true;
    for (const glm::dvec2& c : corners) {
        const glm::dvec2 l = local(q, c);
        if (std::abs(l.x) > 0.5 || std::abs(l.y) > 0.5) {
            all_in = false;
            break;
        }
    }
    if (all_in) return Overlap::Contained;
    // Separating axes: the box's (x, y) and the parallelogram's edge normals.
    const glm::dvec2 half = 0.5 * (glm::abs(q.e1) + glm::abs(q.e2));
    if (q.center.x - half.x > b.lo.x + b.size || q.center.x + half.x < b.lo.x)
        return Overlap::Disjoint;
    if (q.center.y - half.y > b.lo.y + b.size || q.center.y + half.y < b.lo.y)
        return Overlap::Disjoint;
    const glm::dvec2 axes[2] = {{-q.e1.y, q.e1.x}, {-q.e2.y, q.e2.x}};
    for (const glm::dvec2& n : axes) {
        const double c = glm::dot(n, q.center);
        const double r = 0.5 * (std::abs(glm::dot(n, q.e1)) + std::abs(glm::dot(n, q.e2)));
        double lo = 1e300, hi = -1e300;
        for (const glm::dvec2& p : corners) {
            const double v = glm::dot(n, p);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        if (lo > c + r || hi < c - r) return Overlap::Disjoint;
    }
    return Overlap::Partial;
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
