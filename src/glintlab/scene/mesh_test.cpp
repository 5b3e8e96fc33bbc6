#include "glintlab/scene/mesh.h"

#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

TriangleMesh unit_triangle() {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.normals.assign(3, glm::vec3(0, 0, 1));
    m.uvs = {{0, 0}, {1, 0}, {0, 1}};
    m.triangles = {{0, 1, 2}};
    return m;
}

// Expects validate() to throw an Error whose message names the mesh and
// contains `fragment`.
void expect_invalid(const TriangleMesh& m, const std::string& fragment) {
    try {
        m.validate("thing.obj");
        ADD_FAILURE() << "no error for " << fragment;
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("thing.obj"), std::string::npos) << message;
        EXPECT_NE(message.find(fragment), std::string::npos) << message;
    }
}

TEST(MeshValidate, AcceptsConsistentMeshAndRejectsEachDefect) {
    EXPECT_NO_THROW(unit_triangle().validate("ok"));
    expect_invalid(TriangleMesh{}, "no triangles");
    TriangleMesh m = unit_triangle();
    m.triangles[0].z = 3;
    expect_invalid(m, "out of range");
    m = unit_triangle();
    m.normals.pop_back();
    expect_invalid(m, "normals");
    m = unit_triangle();
    m.uvs.push_back({0, 0});
    expect_invalid(m, "uvs");
    m = unit_triangle();
    m.positions[1].y = std::numeric_limits<float>::quiet_NaN();
    expect_invalid(m, "position 1 is not finite");
    m = unit_triangle();
    m.normals[2].x = std::numeric_limits<float>::infinity();
    expect_invalid(m, "normal 2 is not finite");
    m = unit_triangle();
    m.uvs[0].y = std::numeric_limits<float>::quiet_NaN();
    expect_invalid(m, "uv 0 is not finite");
    // Attributes are optional.
    m = unit_triangle();
    m.normals.clear();
    m.uvs.clear();
    EXPECT_NO_THROW(m.validate("bare"));
}

TEST(MeshAppend, OffsetsIndicesAndDropsUnsharedAttributes) {
    TriangleMesh a = unit_triangle();
    append_mesh(a, unit_triangle());
    ASSERT_EQ(a.positions.size(), 6u);
    EXPECT_EQ(a.triangles[1], glm::uvec3(3, 4, 5));
    EXPECT_TRUE(a.has_normals() && a.has_uvs());
    EXPECT_NEAR(surface_area(a), 1.0, 1e-12);  // two right triangles of area 1/2

    TriangleMesh bare = unit_triangle();
    bare.uvs.clear();
    append_mesh(a, bare);
    EXPECT_TRUE(a.has_normals());
    EXPECT_FALSE(a.has_uvs());
    EXPECT_NO_THROW(a.validate("merged"));

    TriangleMesh empty;
    append_mesh(empty, bare);
    EXPECT_EQ(empty.positions, bare.positions);
    EXPECT_FALSE(empty.has_uvs());
}

}  // namespace
}  // namespace glintlab
