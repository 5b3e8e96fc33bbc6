#include "glintlab/glints/jakob2014/spherical_geometry.h"

#include <algorithm>
#include <cmath>

namespace glintlab::jakob2014 {
namespace {

double det3(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    return glm::dot(a, glm::cross(b, c));
}

double cross2(glm::dvec2 a, glm::dvec2 b) {
    return a.x * b.y - a.y * b.x;
}

// Real roots of a t² + b t + c = 0 (numerically stable form); returns how many.
int solve_quadratic(double a, double b, double c, double* t0, double* t1) {
    if (std::abs(a) < 1e-300) {
        if (std::abs(b) < 1e-300) return 0;
        *t0 = *t1 = -c / b;
        return 1;
    }
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return 0;
    const double sq = std::sqrt(disc);
    const double q = -0.5 * (b + std::copysign(sq, b));
    double r0 = q / a, r1 = q != 0.0 ? c / q : r0;
    if (r0 > r1) std::swap(r0, r1);
    *t0 = r0;
    *t1 = r1;
    return 2;
}

}  // namespace

double SphericalTriangle::solid_angle() const {
    const double num = std::abs(det3(v[0], v[1], v[2]));
    const double den = 1.0 + glm::dot(v[0], v[1]) + glm::dot(v[1], v[2]) + glm::dot(v[2], v[0]);
    // Ω = 2 atan(num/den); deep triangles have num/den < 0.1, where the
    // series to x^7 is accurate to 1e-10 relative (atan2 is a hot spot).
    if (den > 0.0 && num < 0.1 * den) {
        const double x = num / den, x2 = x * x;
        return 2.0 * x * (1.0 - x2 * (1.0 / 3.0 - x2 * (1.0 / 5.0 - x2 * (1.0 / 7.0))));
    }
    return 2.0 * std::atan2(num, den);
}

glm::dvec3 SphericalTriangle::center() const {
    return glm::normalize(v[0] + v[1] + v[2]);
}

SphericalTriangle SphericalTriangle::child(int j) const {
    const glm::dvec3 m01 = glm::normalize(v[0] + v[1]);
    const glm::dvec3 m12 = glm::normalize(v[1] + v[2]);
    const glm::dvec3 m20 = glm::normalize(v[2] + v[0]);
    switch (j) {
        case 0:
            return {{v[0], m01, m20}};
        case 1:
            return {{m01, v[1], m12}};
        case 2:
            return {{m20, m12, v[2]}};
        default:
            return {{m01, m12, m20}};
    }
}

bool SphericalTriangle::contains(glm::dvec3 m) const {
    return det3(v[0], v[1], m) >= 0.0 && det3(v[1], v[2], m) >= 0.0 && det3(v[2], v[0], m) >= 0.0;
}

double SphericalTriangle::max_edge_angle() const {
    const double c = std::min({glm::dot(v[0], v[1]), glm::dot(v[1], v[2]), glm::dot(v[2], v[0])});
    return std::acos(std::clamp(c, -1.0, 1.0));
}

SphericalTriangle hemisphere_quadrant(int j) {
    static const glm::dvec3 e[4] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    return {{glm::dvec3(0, 0, 1), e[j & 3], e[(j + 1) & 3]}};
}

SphericalConic SphericalConic::make(glm::dvec3 wi, glm::dvec3 wo, double gamma) {
    SphericalConic k;
    k.gamma = gamma;
    wi = glm::normalize(wi);
    wo = glm::normalize(wo);
    const double cos_g = std::cos(gamma);
    const glm::dvec3 sum = wi + wo, diff = wi - wo;
    // ẑ: the half vector. wi = -wo has no half vector; no normal reflects wi
    // into a cone that excludes -wi... such queries never reach here (both
    // directions lie in the upper hemisphere), but keep a valid frame.
    const glm::dvec3 z = glm::length(sum) > 1e-12 ? glm::normalize(sum) : glm::dvec3(0, 0, 1);
    glm::dvec3 x = glm::cross(wi, wo);
    glm::dvec3 y;
    if (glm::length(x) < 1e-12 || glm::length(diff) < 1e-12) {
        // ωi = ωo: the conic is a circle of radius γ/2 around ẑ; any frame.
        const glm::dvec3 t = std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        x = glm::normalize(glm::cross(z, t));
        y = glm::cross(z, x);
    } else {
        x = glm::normalize(x);
        y = glm::normalize(diff);
    }
    // Eq. 9.
    const double l1 = (glm::dot(wi, wo) + cos_g) / (1.0 - cos_g);
    const double cot_half = 1.0 / std::tan(0.5 * gamma);
    const double l2 = cot_half * cot_half;
    const glm::dmat3 Q(x, y, z);  // columns
    const glm::dmat3 L(glm::dvec3(l1, 0, 0), glm::dvec3(0, l2, 0), glm::dvec3(0, 0, -1));
    k.C = Q * L * glm::transpose(Q);
    k.axis = z;
    // Cap around ẑ containing the elliptic conic: tan²θ <= 1/min(λ1, λ2).
    const double lmin = std::min(l1, l2);
    k.bounded = lmin > 0.0;
    if (k.bounded) {
        const double th = std::atan(1.0 / std::sqrt(lmin));
        k.cos_max = std::cos(th);
        k.sin_max = std::sin(th);
    }
    return k;
}

bool SphericalConic::arc_crosses(glm::dvec3 a, glm::dvec3 b) const {
    const glm::dvec3 c = a + b, d = a - b;
    const glm::dvec3 Cc = C * c, Cd = C * d;
    double t0, t1;
    const int n =
        solve_quadratic(glm::dot(d, Cd), 2.0 * glm::dot(d, Cc), glm::dot(c, Cc), &t0, &t1);
    for (int i = 0; i < n; ++i) {
        const double t = i == 0 ? t0 : t1;
        if (t >= -1.0 && t <= 1.0 && glm::dot(c + t * d, axis) > 0.0) return true;
    }
    return false;
}

Overlap SphericalConic::classify(const SphericalTriangle& t) const {
    const glm::dvec3 c = t.center();
    return classify(t, c, t.cap_cos(c));
}

Overlap SphericalConic::classify(const SphericalTriangle& t, glm::dvec3 c, double cr) const {
    // Quick reject (not in the paper, exact): the conic lies in the cap of
    // radius θmax around ẑ, the triangle in the cap of radius r around its
    // normalised centroid c; caps further apart than r + θmax are disjoint.
    if (bounded && cr > 0.0) {
        const double sr = std::sqrt(std::max(0.0, 1.0 - cr * cr));
        const double cos_sum = cr * cos_max - sr * sin_max;  // cos(r + θmax), r + θmax < π
        if (glm::dot(c, axis) < cos_sum - 1e-12) return Overlap::Disjoint;
    }
    // Quadric values and cross terms of the vertices; the edge quadratic of
    // §3.3 for c = a + b, d = a - b is (q_a + q_b - 2 a^T C b) t² +
    // 2 (q_a - q_b) t + (q_a + q_b + 2 a^T C b).
    const glm::dvec3 Ca = C * t.v[0], Cb = C * t.v[1];
    const double q[3] = {glm::dot(t.v[0], Ca), glm::dot(t.v[1], Cb), glm::dot(t.v[2], C * t.v[2])};
    const double x[3] = {glm::dot(t.v[1], Ca), glm::dot(t.v[2], Cb),
                         glm::dot(t.v[2], Ca)};  // ab, bc, ca
    const double z[3] = {glm::dot(t.v[0], axis), glm::dot(t.v[1], axis), glm::dot(t.v[2], axis)};
    bool inside[3];
    for (int i = 0; i < 3; ++i) inside[i] = q[i] <= 0.0 && z[i] > 0.0;
    if (inside[0] != inside[1] || inside[1] != inside[2]) return Overlap::Partial;
    for (int e = 0; e < 3; ++e) {
        const int i = e, j = (e + 1) % 3;
        double t0, t1;
        const int n = solve_quadratic(q[i] + q[j] - 2.0 * x[e], 2.0 * (q[i] - q[j]),
                                      q[i] + q[j] + 2.0 * x[e], &t0, &t1);
        for (int k = 0; k < n; ++k) {
            const double tt = k == 0 ? t0 : t1;
            if (tt >= -1.0 && tt <= 1.0 && (z[i] + z[j]) + tt * (z[i] - z[j]) > 0.0)
                return Overlap::Partial;
        }
    }
    if (inside[0]) return Overlap::Contained;
    if (t.contains(axis)) return Overlap::Partial;
    return Overlap::Disjoint;
}

double triangle_unit_disk_area(const glm::dvec2 p[3]) {
    // Stokes: area = ½∮ (x dy - y dx) over the boundary of T ∩ disk, which
    // consists of pieces of the triangle's edges inside the disk (½ p×q each)
    // and arcs of the circle where an edge runs outside (½ Δθ each).
    double area = 0.0;
    for (int e = 0; e < 3; ++e) {
        const glm::dvec2 a = p[e], b = p[(e + 1) % 3], d = b - a;
        double ts[4] = {0.0, 0.0, 0.0, 1.0};
        int nt = 1;
        double r0, r1;
        const int n =
            solve_quadratic(glm::dot(d, d), 2.0 * glm::dot(a, d), glm::dot(a, a) - 1.0, &r0, &r1);
        if (n == 2) {
            if (r0 > 0.0 && r0 < 1.0) ts[nt++] = r0;
            if (r1 > 0.0 && r1 < 1.0) ts[nt++] = r1;
        }
        ts[nt++] = 1.0;
        for (int i = 0; i + 1 < nt; ++i) {
            const glm::dvec2 pa = a + ts[i] * d, pb = a + ts[i + 1] * d;
            const glm::dvec2 mid = 0.5 * (pa + pb);
            if (glm::dot(mid, mid) <= 1.0) {
                area += 0.5 * cross2(pa, pb);
            } else {
                area += 0.5 * std::atan2(cross2(pa, pb), glm::dot(pa, pb));
            }
        }
    }
    return std::abs(area);
}

double SphericalConic::overlap_fraction(const SphericalTriangle& t) const {
    // The plane through the vertices, 2-D coordinates (s, u): P = v0 + s e1 + u e2.
    const glm::dvec3 o = t.v[0];
    const glm::dvec3 e1 = glm::normalize(t.v[1] - t.v[0]);
    const glm::dvec3 np = glm::cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
    const double np_len = glm::length(np);
    if (np_len <= 0.0) return contains(t.center()) ? 1.0 : 0.0;
    const glm::dvec3 e2 = glm::cross(np / np_len, e1);
    // q(x) = x^T A x + 2 b^T x + c0 on the plane.
    const glm::dvec3 Ce1 = C * e1, Ce2 = C * e2, Co = C * o;
    const double a11 = glm::dot(e1, Ce1), a12 = glm::dot(e1, Ce2), a22 = glm::dot(e2, Ce2);
    const glm::dvec2 b(glm::dot(e1, Co), glm::dot(e2, Co));
    const double c0 = glm::dot(o, Co);
    const double det = a11 * a22 - a12 * a12;
    glm::dvec2 p[3];
    for (int i = 0; i < 3; ++i) p[i] = {glm::dot(t.v[i] - o, e1), glm::dot(t.v[i] - o, e2)};
    const double tri_area = 0.5 * std::abs(cross2(p[1] - p[0], p[2] - p[0]));
    if (a11 > 0.0 && det > 1e-12 * a11 * a22 && tri_area > 0.0) {
        // Ellipse: centre x0 = -A^{-1} b, q = (x - x0)^T A (x - x0) + k.
        const glm::dvec2 x0(-(a22 * b.x - a12 * b.y) / det, -(-a12 * b.x + a11 * b.y) / det);
        const double k = c0 + glm::dot(b, x0);
        if (k >= 0.0) return 0.0;  // empty
        const glm::dvec3 centre = o + x0.x * e1 + x0.y * e2;
        if (glm::dot(centre, axis) <= 0.0) return 0.0;  // the other nappe
        // A/(-k) = L^T L (Cholesky, L upper triangular): y = L (x - x0) maps
        // the ellipse to the unit disk; area ratios are affine invariant.
        const double s = 1.0 / (-k);
        const double l11 = std::sqrt(a11 * s);
        const double l12 = a12 * s / l11;
        const double l22 = std::sqrt(std::max(0.0, a22 * s - l12 * l12));
        glm::dvec2 y[3];
        for (int i = 0; i < 3; ++i) {
            const glm::dvec2 d = p[i] - x0;
            y[i] = {l11 * d.x + l12 * d.y, l22 * d.y};
        }
        const double ty = 0.5 * std::abs(cross2(y[1] - y[0], y[2] - y[0]));
        if (ty <= 0.0) return 0.0;
        return std::clamp(triangle_unit_disk_area(y) / ty, 0.0, 1.0);
    }
    // Fallback: 16 x 16 stratified points of the planar triangle (square-to-
    // triangle warp), tested against Eq. 8 on the sphere.
    int inside = 0;
    constexpr int kN = 16;
    for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) {
            double u1 = (i + 0.5) / kN, u2 = (j + 0.5) / kN;
            if (u1 + u2 > 1.0) {
                u1 = 1.0 - u1;
                u2 = 1.0 - u2;
            }
            const glm::dvec3 m = t.v[0] + u1 * (t.v[1] - t.v[0]) + u2 * (t.v[2] - t.v[0]);
            if (contains(m)) ++inside;
        }
    return inside / double(kN * kN);
}

}  // namespace glintlab::jakob2014
