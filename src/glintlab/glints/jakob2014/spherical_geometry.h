// Direction-space geometry of jakob2014 (002 §3.2-3.3): spherical triangles of
// the direction tree and the spherical conic section Ω_h of microfacet normals
// that reflect ωi into the cone of radius γ around ωo (Eq. 7-9), with the
// containment, edge-crossing and planar-overlap tests of §3.3. Double
// precision throughout: γ = 0.5° cones and triangles a few arc-seconds wide
// are compared at depth 20.
#pragma once

#include <algorithm>
#include <cstdint>

#include <glm/glm.hpp>

namespace glintlab::jakob2014 {

struct SphericalTriangle {
    glm::dvec3 v[3];  // unit vectors, counter-clockwise seen from outside (det(v0, v1, v2) > 0)

    // Solid angle (Van Oosterom & Strackee 1983).
    double solid_angle() const;
    // Normalised centroid of the vertices (the 1-point rule's node).
    glm::dvec3 center() const;
    // Child j in 0..3 of the edge-midpoint split: the three corner triangles,
    // then the middle one (002 §3.3 "Data structure").
    SphericalTriangle child(int j) const;
    // Three plane-point sidedness tests (002 §3.3).
    bool contains(glm::dvec3 m) const;
    // min_i centre·v_i: cos of the radius of the cap around center().
    double cap_cos(glm::dvec3 c) const {
        return std::min({glm::dot(c, v[0]), glm::dot(c, v[1]), glm::dot(c, v[2])});
    }
    // Largest edge angle (radians).
    double max_edge_angle() const;
};

// Quadrant j in 0..3 of the upper hemisphere (the root's first directional
// split): (n, e_j, e_{j+1}) with e_0 = +x, e_1 = +y, e_2 = -x, e_3 = -y.
SphericalTriangle hemisphere_quadrant(int j);

enum class Overlap { Disjoint, Partial, Contained };

// Ω_h = {m : |m| = 1, m^T C m <= 0, m·ẑ > 0} (Eq. 8-9). C = Q Λ Q^T in the frame
// x̂ = ωi×ωo/|·|, ŷ = (ωi-ωo)/|·|, ẑ = (ωi+ωo)/|·|, Λ = diag(λ1, λ2, -1),
// λ1 = (ωi·ωo + cos γ)/(1 - cos γ), λ2 = cot²(γ/2). The quadric is symmetric
// in m -> -m (a double cone); the nappe around ẑ is the set of normals that
// face both directions, hence the extra condition m·ẑ > 0.
struct SphericalConic {
    glm::dmat3 C{1.0};
    glm::dvec3 axis{0.0, 0.0, 1.0};  // ẑ, always inside (ẑ^T C ẑ = -1)
    double gamma = 0.0;
    // Elliptic case (λ1 > 0): Ω_h lies in the cap of radius θmax around ẑ.
    bool bounded = false;
    double cos_max = -1.0, sin_max = 0.0;

    static SphericalConic make(glm::dvec3 wi, glm::dvec3 wo, double gamma);
    double quadric(glm::dvec3 m) const { return glm::dot(m, C * m); }
    bool contains(glm::dvec3 m) const { return quadric(m) <= 0.0 && glm::dot(m, axis) > 0.0; }
    // Whether the great arc a->b crosses ∂Ω_h: the quadratic
    // d^T C d t² + 2 d^T C c t + c^T C c = 0, c = a + b, d = a - b, has a root in
    // [-1, 1] on the nappe around ẑ (§3.3).
    bool arc_crosses(glm::dvec3 a, glm::dvec3 b) const;
    // §3.3: boundaries disjoint -> C contains T if it contains a vertex,
    // T contains C (partial) if it contains ẑ, else disjoint.
    Overlap classify(const SphericalTriangle& t) const;
    // The same with the triangle's bounding cap given: normalised centroid c
    // and cos of its radius (min_i c·v_i), as cached by the traversal.
    Overlap classify(const SphericalTriangle& t, glm::dvec3 c, double cap_cos) const;
    // σ(T ∩ Ω_h)/σ(T) for a small triangle (line 12 of Algorithm 1): in the
    // plane through the vertices the conic is a planar conic; for an ellipse
    // an affine map makes it the unit disk, where the triangle's overlap is
    // integrated with Stokes' theorem (½∮ x dy - y dx over the line and arc
    // pieces of the boundary). Other planar conics (hyperbolae: only when
    // -ωi is within γ of ωo, i.e. grazing retro-reflection) are estimated
    // from 256 stratified points of the triangle.
    double overlap_fraction(const SphericalTriangle& t) const;
};

// Area of (CCW or CW) triangle p ∩ unit disk via Stokes' theorem.
double triangle_unit_disk_area(const glm::dvec2 p[3]);

}  // namespace glintlab::jakob2014
