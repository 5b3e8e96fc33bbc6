// Affine object-to-world transforms for meshes (scene "transform" entries and
// glTF node matrices).
#pragma once

#include <glm/glm.hpp>

#include "glintlab/scene/mesh.h"

namespace glintlab {

// An affine 4x4 matrix together with its inverse, so normals can be mapped by
// the inverse transpose without re-inverting per use.
struct Transform {
    glm::mat4 m{1.0f};
    glm::mat4 m_inv{1.0f};

    Transform() = default;
    // Throws glintlab::Error if `matrix` is not affine or not invertible.
    explicit Transform(const glm::mat4& matrix);
    Transform(const glm::mat4& matrix, const glm::mat4& inverse) : m(matrix), m_inv(inverse) {}

    static Transform translate(glm::vec3 offset);
    static Transform scale(glm::vec3 factors);  // factors must be non-zero
    // Rotation by `degrees` counter-clockwise about `axis` (right-hand rule).
    static Transform rotate(float degrees, glm::vec3 axis);
    // Places an object at `eye` looking at `target`: its local -z axis maps to
    // the viewing direction and local +y to `up` made orthogonal to it (the
    // OpenGL camera convention; this is the inverse of glm::lookAt).
    static Transform look_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up);

    // Composition: (a * b) applies b first, then a.
    Transform operator*(const Transform& rhs) const {
        return Transform(m * rhs.m, rhs.m_inv * m_inv);
    }
    Transform inverse() const { return Transform(m_inv, m); }

    glm::vec3 apply_point(glm::vec3 p) const { return glm::vec3(m * glm::vec4(p, 1.0f)); }
    glm::vec3 apply_vector(glm::vec3 v) const { return glm::mat3(m) * v; }
    // Normals map by the inverse transpose so they stay perpendicular to the
    // mapped tangents; the result is not normalised.
    glm::vec3 apply_normal(glm::vec3 n) const { return glm::transpose(glm::mat3(m_inv)) * n; }
    // det < 0 means the transform mirrors, which reverses triangle winding.
    bool flips_handedness() const { return glm::determinant(glm::mat3(m)) < 0.0f; }
};

// Transforms positions and normals (inverse transpose, renormalised) in
// place; reverses the winding of every triangle when the transform mirrors,
// so the geometric normal keeps agreeing with the shading normals.
void transform_mesh(TriangleMesh& mesh, const Transform& transform);

}  // namespace glintlab
