// Texture-space part of the jakob2014 query (002 §3.3): the pixel footprint
// is a parallelogram uv ± duvdx/2 ± duvdy/2 (as for every glintlab model);
// tree nodes are axis-aligned boxes. Classification by the separating-axis
// theorem, overlap area by clipping the box against the parallelogram
// (Sutherland-Hodgman), both exact.
#pragma once

#include <glm/glm.hpp>

#include "glintlab/glints/jakob2014/spherical_geometry.h"

namespace glintlab::jakob2014 {

struct UvParallelogram {
    glm::dvec2 center{0.0}, e1{0.0}, e2{0.0};  // points center + a e1 + b e2, |a|, |b| <= 1/2
    double area() const { return std::abs(e1.x * e2.y - e1.y * e2.x); }
    bool contains(glm::dvec2 x) const;
    // Inverse of (e1 e2), half extents of the bounding box and half widths
    // along the edge normals; prepare() fills them after e1, e2 change.
    void prepare();
    glm::dvec2 inv_row0{0.0}, inv_row1{0.0}, half{0.0};
    glm::dvec2 n1{0.0}, n2{0.0};
    double r1 = 0.0, r2 = 0.0;
};

struct UvBox {
    glm::dvec2 lo{0.0};
    double size = 1.0;
};

Overlap classify_box(const UvParallelogram& q, const UvBox& b);
// Area of box ∩ parallelogram.
double box_overlap_area(const UvParallelogram& q, const UvBox& b);

}  // namespace glintlab::jakob2014
