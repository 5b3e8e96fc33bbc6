#include "glintlab/scene/transform.h"

#include <gtest/gtest.h>

#include "glintlab/core/error.h"
#include "glintlab/core/rng.h"
#include "glintlab/scene/shapes.h"

namespace glintlab {
namespace {

// A skewing composite: rotation, non-uniform scale, rotation, translation.
Transform skewed() {
    return Transform::translate({1.0f, -2.0f, 0.5f}) * Transform::rotate(30.0f, {1, 1, 0}) *
           Transform::scale({3.0f, 0.5f, 1.5f}) * Transform::rotate(-50.0f, {0, 1, 2});
}

TEST(MeshTransform, NormalsStayPerpendicularToTangents) {
    const Transform t = skewed();
    const TriangleMesh quad = make_quad({1.0f, 1.0f}, {1.0f, 1.0f});
    TriangleMesh mapped = quad;
    transform_mesh(mapped, t);
    // The quad's edges are tangents; after the transform they must remain
    // perpendicular to the (renormalised) normal: |cos| ~ float rounding of
    // a few matrix products, well below 1e-5.
    for (const glm::uvec3& tri : mapped.triangles)
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 edge =
                glm::normalize(mapped.positions[tri[(k + 1) % 3]] - mapped.positions[tri[k]]);
            EXPECT_NEAR(glm::dot(edge, mapped.normals[tri[k]]), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::length(mapped.normals[tri[k]]), 1.0f, 1e-6f);
        }
    // A scaled sphere is the ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 whose
    // normal is the gradient (x/a^2, y/b^2, z/c^2): an exact check of the
    // inverse transpose.
    const glm::vec3 abc(3.0f, 0.5f, 1.5f);
    TriangleMesh sphere = make_sphere(1.0f, 16, 8);
    transform_mesh(sphere, Transform::scale(abc));
    for (size_t i = 0; i < sphere.positions.size(); ++i) {
        const glm::vec3 gradient = glm::normalize(sphere.positions[i] / (abc * abc));
        EXPECT_LE(glm::distance(sphere.normals[i], gradient), 1e-5f);
    }
}

TEST(MeshTransform, MirrorFlipsWindingSoGeometricNormalsAgree) {
    for (const glm::vec3& factors : {glm::vec3(-1, 1, 1), glm::vec3(2, -0.5f, 3)}) {
        const Transform t = Transform::scale(factors) * Transform::rotate(20.0f, {1, 0, 0});
        EXPECT_TRUE(t.flips_handedness());
        TriangleMesh sphere = make_sphere(1.0f, 12, 6);
        const auto original = sphere.triangles;
        transform_mesh(sphere, t);
        for (size_t k = 0; k < original.size(); ++k) {
            // The winding is reversed (b and c swapped)...
            EXPECT_EQ(sphere.triangles[k], glm::uvec3(original[k].x, original[k].z, original[k].y));
            // ...so geometric normals still agree with the shading normals and
            // point outward from the (origin-centred) ellipsoid.
            const glm::vec3 ng = geometric_normal(sphere, k);
            const glm::uvec3 tri = sphere.triangles[k];
            EXPECT_GT(glm::dot(ng, sphere.normals[tri.x]), 0.0f);
            EXPECT_GT(glm::dot(ng, sphere.positions[tri.x] + sphere.positions[tri.y] +
                                       sphere.positions[tri.z]),
                      0.0f);
        }
    }
    EXPECT_FALSE(skewed().flips_handedness());
}

TEST(MeshTransform, CompositionInverseAndConventions) {
    const Transform a = skewed();
    const Transform b = Transform::rotate(75.0f, {0, 0, 1}) * Transform::translate({0, 3, 0});
    Pcg32 rng(7, 1);
    for (int k = 0; k < 100; ++k) {
        const glm::vec3 p(rng.next_float() * 4 - 2, rng.next_float() * 4 - 2,
                          rng.next_float() * 4 - 2);
        // Values ~10 after the transforms: float rounding ~1e-5 absolute.
        EXPECT_LE(glm::distance((a * b).apply_point(p), a.apply_point(b.apply_point(p))), 1e-4f);
        EXPECT_LE(glm::distance((a * b).inverse().apply_point((a * b).apply_point(p)), p), 1e-4f);
    }
    // Right-hand rule: +90 degrees about +y takes +x to -z.
    EXPECT_LE(glm::distance(Transform::rotate(90.0f, {0, 1, 0}).apply_vector({1, 0, 0}),
                            glm::vec3(0, 0, -1)),
              1e-6f);
    // look_at: the origin goes to the eye and local -z towards the target.
    const Transform view = Transform::look_at({1, 2, 3}, {1, 2, -7}, {0, 1, 0});
    EXPECT_LE(glm::distance(view.apply_point({0, 0, 0}), glm::vec3(1, 2, 3)), 1e-6f);
    EXPECT_LE(glm::distance(view.apply_vector({0, 0, -1}), glm::vec3(0, 0, -1)), 1e-6f);
    EXPECT_LE(glm::distance(view.apply_vector({0, 1, 0}), glm::vec3(0, 1, 0)), 1e-6f);
}

TEST(MeshTransform, RejectsDegenerateTransforms) {
    EXPECT_THROW(Transform::scale({1.0f, 0.0f, 1.0f}), Error);
    EXPECT_THROW(Transform::rotate(10.0f, {0, 0, 0}), Error);
    EXPECT_THROW(Transform::look_at({0, 0, 0}, {0, 1, 0}, {0, 1, 0}), Error);
    glm::mat4 singular(1.0f);
    singular[2][2] = 0.0f;
    EXPECT_THROW(Transform{singular}, Error);
    glm::mat4 projective(1.0f);
    projective[2][3] = -1.0f;
    EXPECT_THROW(Transform{projective}, Error);
}

}  // namespace
}  // namespace glintlab
