#include "glintlab/scene/shapes_heightfield.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

// Angle between two non-zero vectors, robust for tiny angles.
float angle_between(glm::vec3 a, glm::vec3 b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

TEST(MeshHeightfield, ZeroAmplitudeIsThePlane) {
    HeightfieldSettings s;
    s.size = {3.0f, 1.5f};
    s.resolution = 16;
    s.amplitude = 0.0f;
    s.uv_scale = {2.0f, 4.0f};
    const TriangleMesh mesh = make_heightfield(s);
    mesh.validate("heightfield");
    ASSERT_EQ(mesh.positions.size(), 17u * 17u);
    ASSERT_EQ(mesh.triangles.size(), 2u * 16u * 16u);
    for (size_t k = 0; k < mesh.positions.size(); ++k) {
        const glm::vec3 p = mesh.positions[k];
        EXPECT_EQ(p.y, 0.0f);
        EXPECT_EQ(mesh.normals[k], glm::vec3(0, 1, 0));
        // uv of the undisplaced plane, laid out like make_quad: u along +x,
        // v along -z; i / 16 is exact in float so the comparison is tight.
        const glm::vec2 uv = mesh.uvs[k] / s.uv_scale;
        EXPECT_NEAR(p.x, (uv.x - 0.5f) * s.size.x, 1e-6f);
        EXPECT_NEAR(p.z, (0.5f - uv.y) * s.size.y, 1e-6f);
    }
    // Flat: the area is that of the plane, up to float rounding.
    EXPECT_NEAR(surface_area(mesh), 4.5, 1e-5);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        EXPECT_GT(geometric_normal(mesh, t).y, 0.0f);  // counter-clockwise from above
}

TEST(MeshHeightfield, NormalsMatchFiniteDifferencesOfPositions) {
    HeightfieldSettings s;
    s.resolution = 64;
    s.amplitude = 0.05f;
    const TriangleMesh mesh = make_heightfield(s);
    const int n = s.resolution, stride = n + 1;
    auto p = [&](int i, int j) { return mesh.positions[static_cast<size_t>(j * stride + i)]; };
    float max_height = 0.0f, max_tilt = 0.0f;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            // The normal is built from differences of the same height samples
            // the positions use, so it must equal the cross product of the
            // position differences up to float rounding (positions ~1,
            // differences ~1/32: relative error ~1e-7 * 32 ~ 3e-6 rad).
            const glm::vec3 du = p(std::min(i + 1, n), j) - p(std::max(i - 1, 0), j);
            const glm::vec3 dv = p(i, std::min(j + 1, n)) - p(i, std::max(j - 1, 0));
            const glm::vec3 normal = mesh.normals[static_cast<size_t>(j * stride + i)];
            EXPECT_LE(angle_between(normal, glm::cross(du, dv)), 2e-5f) << i << "," << j;
            max_height = std::max(max_height, std::abs(p(i, j).y));
            max_tilt = std::max(max_tilt, angle_between(normal, glm::vec3(0, 1, 0)));
        }
    // The surface really is displaced (value noise reaches a good fraction
    // of its range) and the normals really tilt, so the check above is not
    // vacuous.
    EXPECT_GT(max_height, 0.2f * s.amplitude);
    EXPECT_LE(max_height, s.amplitude);
    EXPECT_GT(max_tilt, 0.05f);
}

TEST(MeshHeightfield, CallbackNormalsConvergeToAnalytic) {
    // h(u, v) = sin(2 pi u) cos(2 pi v). Central differences at spacing h
    // have slope error <= h^2 / 6 max|f'''| with f''' <= A (2 pi)^3 in uv
    // units; dividing by the plane size gives world slopes, and the normal's
    // angle error is at most the slope error. One-sided border differences
    // are first order: error <= h / 2 max|f''| with f'' <= A (2 pi)^2.
    HeightfieldSettings s;
    s.size = {2.0f, 2.0f};
    s.resolution = 128;
    s.amplitude = 0.05f;
    const float two_pi = glm::two_pi<float>();
    auto height = [&](glm::vec2 uv) { return std::sin(two_pi * uv.x) * std::cos(two_pi * uv.y); };
    const TriangleMesh mesh = make_heightfield(s, height);
    const float h = 1.0f / s.resolution;
    const float a = s.amplitude;
    const float interior_bound = h * h / 6.0f * a * std::pow(two_pi, 3.0f) / s.size.x + 2e-6f;
    const float border_bound = h / 2.0f * a * two_pi * two_pi / s.size.x + 2e-6f;
    const int stride = s.resolution + 1;
    for (int j = 0; j <= s.resolution; ++j)
        for (int i = 0; i <= s.resolution; ++i) {
            const glm::vec2 uv(i * h, j * h);
            const float yu = a * two_pi * std::cos(two_pi * uv.x) * std::cos(two_pi * uv.y);
            const float yv = -a * two_pi * std::sin(two_pi * uv.x) * std::sin(two_pi * uv.y);
            const glm::vec3 exact(-s.size.y * yu, s.size.x * s.size.y, s.size.x * yv);
            const bool border = i == 0 || j == 0 || i == s.resolution || j == s.resolution;
            EXPECT_LE(angle_between(mesh.normals[static_cast<size_t>(j * stride + i)], exact),
                      border ? border_bound : interior_bound)
                << i << "," << j;
        }
}

TEST(MeshHeightfield, DeterministicPerSeed) {
    HeightfieldSettings s;
    s.resolution = 32;
    const TriangleMesh a = make_heightfield(s);
    const TriangleMesh b = make_heightfield(s);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    s.seed = 2;
    const TriangleMesh c = make_heightfield(s);
    float max_difference = 0.0f;
    for (size_t k = 0; k < a.positions.size(); ++k)
        max_difference = std::max(max_difference, std::abs(a.positions[k].y - c.positions[k].y));
    // Independent lattices: over 33^2 samples the heights must differ by a
    // sizeable fraction of the amplitude somewhere.
    EXPECT_GT(max_difference, 0.2f * s.amplitude);
}

TEST(MeshHeightfield, ProceduralHeightStaysInUnitRange) {
    HeightfieldSettings s;
    s.octaves = 6;
    for (int k = 0; k < 4096; ++k) {
        const glm::vec2 uv((k % 64) / 63.0f * 1.7f, (k / 64) / 63.0f * 1.3f);
        const float v = procedural_height(s, uv);
        ASSERT_TRUE(v >= -1.0f && v <= 1.0f) << v;
    }
}

TEST(MeshHeightfield, RejectsInvalidSettings) {
    HeightfieldSettings s;
    s.resolution = 0;
    EXPECT_THROW(make_heightfield(s), Error);
    s = {};
    s.octaves = 0;
    EXPECT_THROW(make_heightfield(s), Error);
    s = {};
    s.size = {-1.0f, 1.0f};
    EXPECT_THROW(make_heightfield(s), Error);
}

}  // namespace
}  // namespace glintlab
