// Vertex tangents for normal maps (scene/mesh_tangents.h): on a torus, whose
// ∂p/∂u is known in closed form, the generated frames are the analytic ones
// away from the uv seam, with one bitangent sign; on the seam's split
// vertices they are one-sided, as MikkTSpace's (the frames a baker used);
// a mirrored uv mapping flips the sign; degenerate uvs are counted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glintlab/scene/mesh_tangents.h"
#include "glintlab/scene/shapes.h"

namespace glintlab {
namespace {

struct Worst {
    double interior = 0.0, seam = 0.0;
};

Worst worst_tangent_angle(int segments_major, int segments_minor, float* sign) {
    TriangleMesh torus = make_torus(1.0f, 0.35f, segments_major, segments_minor, {1.0f, 1.0f});
    EXPECT_EQ(generate_vertex_tangents(torus), 0u);
    Worst worst;
    *sign = torus.tangents[0].w;
    for (size_t v = 0; v < torus.positions.size(); ++v) {
        const glm::vec3 p = torus.positions[v];
        // u = a / 2π with p = ((R + r cos b) cos a, r sin b, −(R + r cos b) sin a):
        // ∂p/∂a ∝ (−sin a, 0, −cos a) = (p.z, 0, −p.x) / |(p.x, p.z)|.
        const glm::vec3 analytic = glm::normalize(glm::vec3(p.z, 0.0f, -p.x));
        const glm::vec3 t = glm::vec3(torus.tangents[v]);
        const double angle = std::acos(std::clamp(glm::dot(t, analytic), -1.0f, 1.0f));
        const bool seam = torus.uvs[v].x == 0.0f || torus.uvs[v].x == 1.0f;
        double& w = seam ? worst.seam : worst.interior;
        w = std::max(w, angle);
        EXPECT_EQ(torus.tangents[v].w, *sign) << v;
        EXPECT_NEAR(glm::dot(t, torus.normals[v]), 0.0f, 1e-5f) << v;
    }
    return worst;
}

TEST(MeshTangents, ATorusGetsItsAnalyticTangentsAwayFromItsSeam) {
    float coarse_sign = 0.0f, fine_sign = 0.0f;
    const Worst coarse = worst_tangent_angle(24, 12, &coarse_sign);
    const Worst fine = worst_tangent_angle(48, 24, &fine_sign);
    // Inside, the angle-weighted mean of the two sides' ∂p/∂u is the
    // analytic direction by the grid's symmetry (a one-sided tangent is off
    // by half a segment, π/24 ≈ 0.13 rad at 24 segments).
    EXPECT_LT(coarse.interior, 1e-3) << coarse.interior;
    EXPECT_LT(fine.interior, 1e-3) << fine.interior;
    // On the seam one side's: half a segment, halving with the segment.
    EXPECT_NEAR(coarse.seam, std::numbers::pi / 24.0, 1e-3);
    EXPECT_NEAR(fine.seam, std::numbers::pi / 48.0, 1e-3);
    EXPECT_EQ(coarse_sign, fine_sign);
}

TEST(MeshTangents, AMirroredUvMappingFlipsTheBitangentSign) {
    TriangleMesh quad;
    quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    quad.normals.assign(4, glm::vec3(0, 0, 1));
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    // v down the image while y goes up: n × t = +y is "up", w = +1.
    quad.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    generate_vertex_tangents(quad);
    for (const glm::vec4& t : quad.tangents) {
        EXPECT_NEAR(glm::distance(glm::vec3(t), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
        EXPECT_EQ(t.w, 1.0f);
    }
    quad.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // mirrored: v runs up the image
    generate_vertex_tangents(quad);
    for (const glm::vec4& t : quad.tangents) EXPECT_EQ(t.w, -1.0f);
    quad.uvs.assign(4, glm::vec2(0.5f));  // no direction of u anywhere
    EXPECT_EQ(generate_vertex_tangents(quad), 4u);
    for (const glm::vec4& t : quad.tangents) {
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-6f);
        EXPECT_NEAR(t.z, 0.0f, 1e-6f);  // orthogonal to the normal
    }
}

}  // namespace
}  // namespace glintlab
