#include "glintlab/scene/shapes.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

constexpr double kPi = glm::pi<double>();

// Every triangle's geometric normal must point to the same side as its
// vertex normals (the winding convention of mesh.h).
void expect_winding_matches_normals(const TriangleMesh& mesh) {
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::vec3 ng = geometric_normal(mesh, t);
        ASSERT_GT(glm::length(ng), 0.0f) << "degenerate triangle " << t;
        for (int k = 0; k < 3; ++k)
            ASSERT_GT(glm::dot(ng, mesh.normals[mesh.triangles[t][k]]), 0.0f) << "triangle " << t;
    }
}

// No triangle spans a seam: its uvs differ by at most one grid step (plus
// float rounding of i / n, far below 1e-5).
void expect_uvs_continuous(const TriangleMesh& mesh, glm::vec2 max_step) {
    for (const glm::uvec3& t : mesh.triangles)
        for (int a = 0; a < 3; ++a) {
            const glm::vec2 d = glm::abs(mesh.uvs[t[a]] - mesh.uvs[t[(a + 1) % 3]]);
            ASSERT_LE(d.x, max_step.x + 1e-5f);
            ASSERT_LE(d.y, max_step.y + 1e-5f);
        }
}

TEST(MeshShapes, QuadAreaUvRangeAndRightHandedFrame) {
    const glm::vec2 size(3.0f, 2.0f), uv_scale(4.0f, 5.0f);
    const TriangleMesh quad = make_quad(size, uv_scale);
    quad.validate("quad");
    // Two exact triangles: the area is exact up to float rounding.
    EXPECT_NEAR(surface_area(quad), 6.0, 1e-6);
    expect_winding_matches_normals(quad);
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (glm::vec2 uv : quad.uvs) lo = glm::min(lo, uv), hi = glm::max(hi, uv);
    EXPECT_EQ(lo, glm::vec2(0.0f));
    EXPECT_EQ(hi, uv_scale);
    // dp/du and dp/dv of each triangle from its edges: solve
    // [e1 e2] = [dpdu dpdv] [duv1 duv2].
    for (const glm::uvec3& t : quad.triangles) {
        const glm::vec3 e1 = quad.positions[t.y] - quad.positions[t.x];
        const glm::vec3 e2 = quad.positions[t.z] - quad.positions[t.x];
        const glm::vec2 d1 = quad.uvs[t.y] - quad.uvs[t.x];
        const glm::vec2 d2 = quad.uvs[t.z] - quad.uvs[t.x];
        const float det = d1.x * d2.y - d1.y * d2.x;
        const glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) / det;
        const glm::vec3 dpdv = (e2 * d1.x - e1 * d2.x) / det;
        // Documented: u along +x, v along -z, with |dp/du| = size.x / uv_scale.x.
        EXPECT_NEAR(glm::distance(dpdu, glm::vec3(size.x / uv_scale.x, 0, 0)), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::distance(dpdv, glm::vec3(0, 0, -size.y / uv_scale.y)), 0.0f, 1e-6f);
        const glm::vec3 n = quad.normals[t.x];
        EXPECT_EQ(n, glm::vec3(0, 1, 0));
        EXPECT_GT(glm::dot(glm::cross(dpdu, dpdv), n), 0.0f);  // right-handed
    }
}

TEST(MeshShapes, SphereAreaConvergesQuadratically) {
    // The tessellation is inscribed in the convex sphere, so its area is
    // smaller (surface area is monotone under inclusion of convex bodies):
    // deficit e > 0. Radially projecting a facet onto the sphere stretches
    // areas by at most 1 / cos^2(rho), rho the facet's angular circumradius,
    // so e <= sin^2(rho) <= rho^2 with rho <= half the cell's angular
    // diagonal: e <= (dphi^2 + dtheta^2) / 4. Halving the steps must divide
    // e by ~4 (second order).
    const float radius = 1.7f;
    const double exact = 4.0 * kPi * radius * radius;
    double previous = 0.0;
    for (int n : {16, 32, 64, 128}) {
        const TriangleMesh sphere = make_sphere(radius, n, n / 2);
        const double e = 1.0 - surface_area(sphere) / exact;
        const double dphi = 2.0 * kPi / n, dtheta = kPi / (n / 2);
        EXPECT_GT(e, 0.0) << n;
        EXPECT_LE(e, (dphi * dphi + dtheta * dtheta) / 4.0) << n;
        if (previous > 0.0) {
            EXPECT_NEAR(previous / e, 4.0, 0.3) << n;
        }
        previous = e;
    }
}

TEST(MeshShapes, SphereNormalsUvsAndWinding) {
    const float radius = 2.0f;
    const int segments = 24, rings = 12;
    const TriangleMesh sphere = make_sphere(radius, segments, rings);
    sphere.validate("sphere");
    for (size_t i = 0; i < sphere.positions.size(); ++i) {
        // Analytic normal p / r; float rounding of sin/cos products ~1e-7.
        EXPECT_NEAR(glm::length(sphere.normals[i]), 1.0f, 1e-6f);
        EXPECT_LE(glm::distance(sphere.normals[i], sphere.positions[i] / radius), 1e-6f);
        const glm::vec2 uv = sphere.uvs[i];
        EXPECT_TRUE(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f);
        // uv = (phi / 2pi, theta / pi) with theta from +y.
        EXPECT_NEAR(std::acos(glm::clamp(sphere.normals[i].y, -1.0f, 1.0f)) / glm::pi<float>(),
                    uv.y, 1e-4f);
    }
    expect_winding_matches_normals(sphere);
    expect_uvs_continuous(sphere, glm::vec2(1.0f / segments, 1.0f / rings));
    // Every triangle of the pole rows except one degenerate half per cell.
    EXPECT_EQ(sphere.triangles.size(), static_cast<size_t>(2 * segments * (rings - 1)));
}

TEST(MeshShapes, TorusAreaConvergesQuadratically) {
    // Pappus: area = (2 pi R)(2 pi r). The facet normal deviates from the
    // surface normal by at most about half the cell's angular diagonal
    // (normals turn by <= da along the major direction, db along the minor),
    // so the relative area error is bounded like the sphere's,
    // |e| <= (da^2 + db^2) / 4, and is second order: ratio ~4 per halving.
    const float major = 2.0f, minor = 0.5f;
    const double exact = 4.0 * kPi * kPi * major * minor;
    double previous = 0.0;
    for (int n : {16, 32, 64, 128}) {
        const TriangleMesh torus = make_torus(major, minor, 2 * n, n, glm::vec2(1.0f));
        const double e = 1.0 - surface_area(torus) / exact;
        const double da = 2.0 * kPi / (2 * n), db = 2.0 * kPi / n;
        EXPECT_LE(std::abs(e), (da * da + db * db) / 4.0) << n;
        if (previous != 0.0) {
            EXPECT_NEAR(previous / e, 4.0, 0.3) << n;
        }
        previous = e;
    }
}

TEST(MeshShapes, TorusNormalsUvsAndWinding) {
    const float major = 1.5f, minor = 0.4f;
    const int sm = 32, sn = 12;
    const glm::vec2 uv_scale(8.0f, 2.0f);
    const TriangleMesh torus = make_torus(major, minor, sm, sn, uv_scale);
    torus.validate("torus");
    for (size_t i = 0; i < torus.positions.size(); ++i) {
        const glm::vec3 p = torus.positions[i];
        // Analytic normal: away from the nearest point of the tube's core circle.
        const glm::vec3 core = major * glm::normalize(glm::vec3(p.x, 0.0f, p.z));
        EXPECT_NEAR(glm::length(torus.normals[i]), 1.0f, 1e-6f);
        EXPECT_LE(glm::distance(torus.normals[i], (p - core) / minor), 1e-5f);
        const glm::vec2 uv = torus.uvs[i];
        EXPECT_TRUE(uv.x >= 0.0f && uv.x <= uv_scale.x && uv.y >= 0.0f && uv.y <= uv_scale.y);
    }
    expect_winding_matches_normals(torus);
    expect_uvs_continuous(torus, uv_scale / glm::vec2(sm, sn));
}

TEST(MeshShapes, HeadNormalsUvsWindingAndFeatures) {
    const int sp = 96, rt = 48;
    const TriangleMesh head = make_head(sp, rt, glm::vec2(1.0f));
    head.validate("head");
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (size_t i = 0; i < head.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(head.normals[i]), 1.0f, 1e-5f);
        // Star-shaped about the origin: normals never point inwards.
        EXPECT_GT(glm::dot(head.normals[i], glm::normalize(head.positions[i])), 0.0f) << i;
        lo = glm::min(lo, head.positions[i]);
        hi = glm::max(hi, head.positions[i]);
    }
    expect_winding_matches_normals(head);
    expect_uvs_continuous(head, glm::vec2(1.0f / sp, 1.0f / rt));
    // Ears stick out sideways (radius 1 + 0.55, x scale 0.95) and the muzzle
    // forwards (1 + ~0.28, z scale 0.92) beyond the unit sphere.
    EXPECT_GT(hi.x, 1.35f);
    EXPECT_LT(lo.x, -1.35f);
    EXPECT_GT(hi.z, 1.05f);
}

TEST(MeshShapes, RejectsInvalidParameters) {
    EXPECT_THROW(make_quad({0.0f, 1.0f}, {1, 1}), Error);
    EXPECT_THROW(make_sphere(-1.0f, 8, 4), Error);
    EXPECT_THROW(make_sphere(1.0f, 2, 4), Error);
    EXPECT_THROW(make_sphere(1.0f, 8, 1), Error);
    EXPECT_THROW(make_torus(1.0f, 0.0f, 8, 8, {1, 1}), Error);
    EXPECT_THROW(make_torus(1.0f, 0.2f, 8, 2, {1, 1}), Error);
}

}  // namespace
}  // namespace glintlab
