// Generated uv parameterizations for meshes that have none (or whose uvs a
// scene replaces): box, planar, cylindrical and spherical projections in the
// mesh's object space (docs/SCENE_FORMAT.md, "uv" of shapes).
#pragma once

#include <glm/glm.hpp>

#include "glintlab/scene/mesh.h"

namespace glintlab {

struct UvProjection {
    enum class Type { Box, Planar, Cylindrical, Spherical };
    Type type = Type::Box;
    // uv units per object-space unit: a surface patch of area A (object
    // units², on a face the projection does not stretch) covers S²·A of uv.
    float scale = 1.0f;
    // 0, 1, 2 = x, y, z: the plane's normal (planar), the cylinder's or the
    // sphere's polar axis. Frames per axis a = (t, b, a), right-handed:
    // x → (−z, y, x), y → (x, −z, y), z → (x, y, z).
    int axis = 1;
    glm::vec3 center{0.0f};  // origin of the projection (object space)
    // Reference radius ρ of cylindrical/spherical; ≤ 0: the largest distance
    // of a vertex from the axis (cylindrical) or the center (spherical).
    float radius = 0.0f;
};

// The frame (t, b, n) of axis `axis` (0, 1, 2), or of the box face whose
// outward normal is ±axis (sign < 0: the opposite face): t × b = n.
void uv_projection_frame(int axis, int sign, glm::vec3* t, glm::vec3* b, glm::vec3* n);

// Replaces mesh.uvs by the projection's uvs (p relative to center, in the
// frame of `axis`; φ = atan2(p·b, p·t), ρ the reference radius):
//   planar       u = S p·t,  v = S p·b
//   box          per triangle, the face ±x/±y/±z of the largest component of
//                its geometric normal, then planar in that face's frame
//   cylindrical  u = S ρ φ,  v = S p·n
//   spherical    u = S ρ φ,  v = S ρ (p·n)/|p| (Lambert's equal-area
//                cylindrical projection of the direction of p)
// A vertex whose uv differs between the triangles using it (box faces,
// the φ = ±π seam, poles) is duplicated, so no triangle interpolates across
// a face change or the wrap: each triangle's φ values are unwrapped to lie
// within π of its first corner, and a corner on the axis (φ undefined) takes
// the mean φ of the triangle's other corners. Normals follow their vertices.
void project_uvs(TriangleMesh& mesh, const UvProjection& projection);

}  // namespace glintlab
