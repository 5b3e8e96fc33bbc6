#include "glintlab/scene/transform.h"

#include <cmath>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "glintlab/core/error.h"

namespace glintlab {

Transform::Transform(const glm::mat4& matrix) : m(matrix) {
    // An affine matrix has (0, 0, 0, 1) as its last row (glm is column-major:
    // m[column][row]).
    if (matrix[0][3] != 0.0f || matrix[1][3] != 0.0f || matrix[2][3] != 0.0f ||
        matrix[3][3] != 1.0f)
        fail("transform: matrix is not affine (last row must be 0 0 0 1)");
    const float det = glm::determinant(glm::mat3(matrix));
    if (!std::isfinite(det) || det == 0.0f) fail("transform: matrix is singular (det = {})", det);
    m_inv = glm::inverse(matrix);
}

Transform Transform::translate(glm::vec3 offset) {
    return Transform(glm::translate(glm::mat4(1.0f), offset),
                     glm::translate(glm::mat4(1.0f), -offset));
}

Transform Transform::scale(glm::vec3 factors) {
    if (factors.x == 0.0f || factors.y == 0.0f || factors.z == 0.0f)
        fail("transform: scale factors must be non-zero, got ({}, {}, {})", factors.x, factors.y,
             factors.z);
    return Transform(glm::scale(glm::mat4(1.0f), factors),
                     glm::scale(glm::mat4(1.0f), 1.0f / factors));
}

Transform Transform::rotate(float degrees, glm::vec3 axis) {
    const float len = glm::length(axis);
    if (!(len > 0.0f)) fail("transform: rotation axis must be non-zero");
    const glm::mat4 r = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), axis / len);
    // A rotation's inverse is its transpose.
    return Transform(r, glm::transpose(r));
}

Transform Transform::look_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up) {
    const glm::vec3 dir = target - eye;
    if (!(glm::length(dir) > 0.0f)) fail("transform: look_at eye and target coincide");
    if (!(glm::length(glm::cross(dir, up)) > 0.0f))
        fail("transform: look_at up vector is parallel to the viewing direction");
    const glm::mat4 world_to_local = glm::lookAt(eye, target, up);
    return Transform(glm::inverse(world_to_local), world_to_local);
}

void transform_mesh(TriangleMesh& mesh, const Transform& transform) {
    for (glm::vec3& p : mesh.positions) p = transform.apply_point(p);
    for (glm::vec3& n : mesh.normals) {
        const glm::vec3 mapped = transform.apply_normal(n);
        const float len = glm::length(mapped);
        n = len > 0.0f ? mapped / len : mapped;
    }
    // Tangents map as directions; a mirroring transform flips the
    // bitangent's sign so that n × t · w keeps following ∂p/∂v's image.
    const float sign = transform.flips_handedness() ? -1.0f : 1.0f;
    for (glm::vec4& t : mesh.tangents) {
        const glm::vec3 mapped = transform.apply_vector(glm::vec3(t));
        const float len = glm::length(mapped);
        t = glm::vec4(len > 0.0f ? mapped / len : mapped, sign * t.w);
    }
    if (transform.flips_handedness())
        for (glm::uvec3& t : mesh.triangles) std::swap(t.y, t.z);
}

}  // namespace glintlab
