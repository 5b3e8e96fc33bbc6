// Procedural shapes with analytic normals and well-defined per-vertex uvs.
// Every shape follows the TriangleMesh winding convention (counter-clockwise
// seen from outside, geometric normal = shading normal side).
#pragma once

#include <glm/glm.hpp>

#include "glintlab/scene/mesh.h"

namespace glintlab {

// Rectangle of `size` (x by z) in the xz plane (y up), centred at the origin,
// normal +y. uv spans [0, uv_scale.x] x [0, uv_scale.y] with u along +x and v
// along -z, so (dp/du, dp/dv, n) = (+x, -z, +y) is a right-handed frame:
// cross(dp/du, dp/dv) points along n.
TriangleMesh make_quad(glm::vec2 size, glm::vec2 uv_scale);

// Sphere centred at the origin; theta is measured from the +y pole and phi
// about the y axis: p = r (sin t cos p, cos t, sin t sin p).
// uv = (phi / 2pi, theta / pi); the phi = 0 / 2pi seam is duplicated so no
// triangle spans it. The pole triangles that would be degenerate are omitted.
// segments_phi >= 3, rings_theta >= 2.
TriangleMesh make_sphere(float radius, int segments_phi, int rings_theta);

// Torus about the y axis: major angle a about y, minor angle b around the
// tube, p = ((R + r cos b) cos a, r sin b, -(R + r cos b) sin a).
// uv = (a / 2pi, b / 2pi) * uv_scale; both seams duplicated.
// segments_major >= 3, segments_minor >= 3.
TriangleMesh make_torus(float major_radius, float minor_radius, int segments_major,
                        int segments_minor, glm::vec2 uv_scale);

// A monkey-like head, glintlab's procedural stand-in for 000's MONKEY scene
// (no CC0 Suzanne with uvs is available offline): a sphere of radius ~1
// (facing +z, y up) deformed by smooth bumps into a skull with muzzle, brow,
// eye sockets and ears, so it has the curvature range of a character mesh.
// Same uv and grid layout as make_sphere (u = phi / 2pi with the seam at the
// back, v = theta / pi from the +y pole), scaled by uv_scale; normals are the
// normalised cross product of the parametric tangents. Released as CC0 with
// glintlab (it is generated, not copied).
TriangleMesh make_head(int segments_phi, int rings_theta, glm::vec2 uv_scale);

}  // namespace glintlab
