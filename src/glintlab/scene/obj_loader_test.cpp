#include "glintlab/scene/obj_loader.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

namespace fs = std::filesystem;

// Writes OBJ snippets into a per-test temporary directory removed afterwards.
class MeshObj : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("glintlab_obj_" + std::to_string(::getpid()) + "_" + info->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path path = dir_ / name;
        std::ofstream(path) << text;
        return path;
    }

    // Expects load_obj to throw an Error naming the file.
    void expect_error(const fs::path& path, const std::string& fragment) const {
        try {
            load_obj(path);
            ADD_FAILURE() << "no error for " << path;
        } catch (const Error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
            EXPECT_NE(message.find(fragment), std::string::npos) << message;
        }
    }

    fs::path dir_;
};

TEST_F(MeshObj, QuadWithTexcoordsAndNormals) {
    const TriangleMesh m = load_obj(write("quad.obj",
                                          "# unit quad in the xz plane\n"
                                          "v -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\n"
                                          "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                          "vn 0 2 0\n"  // not unit: normalised on load
                                          "f 1/1/1 2/2/1 3/3/1 4/4/1\n"));
    // The quad face is split into 2 triangles over its 4 shared corners.
    ASSERT_EQ(m.triangles.size(), 2u);
    ASSERT_EQ(m.positions.size(), 4u);
    ASSERT_TRUE(m.has_uvs() && m.has_normals());
    EXPECT_NEAR(surface_area(m), 4.0, 1e-6);
    for (size_t i = 0; i < 4; ++i) {
        // vt k belongs to v k in this file: u = (x + 1) / 2, v = (1 - z) / 2.
        const glm::vec3 p = m.positions[i];
        EXPECT_EQ(m.uvs[i], glm::vec2((p.x + 1) / 2, (1 - p.z) / 2));
        EXPECT_EQ(m.normals[i], glm::vec3(0, 1, 0));
    }
    for (size_t t = 0; t < m.triangles.size(); ++t)
        EXPECT_GT(geometric_normal(m, t).y, 0.0f);  // OBJ faces are counter-clockwise
}

TEST_F(MeshObj, WithoutTexcoordsHasNoUvs) {
    const TriangleMesh m =
        load_obj(write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n"));
    EXPECT_EQ(m.triangles.size(), 1u);
    EXPECT_FALSE(m.has_uvs());
    EXPECT_TRUE(m.has_normals());
    const TriangleMesh bare = load_obj(write("bare.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_FALSE(bare.has_uvs() || bare.has_normals());
}

TEST_F(MeshObj, PolygonsTriangulatedShapesMergedAndVerticesDeindexed) {
    // A regular-ish convex pentagon (object A) and a quad (object B) sharing
    // no data; B's corners reuse positions of A with different uvs, which
    // must become separate vertices.
    const TriangleMesh m = load_obj(write("poly.obj",
                                          "v 0 0 0\nv 2 0 0\nv 3 2 0\nv 1 3 0\nv -1 2 0\n"
                                          "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                                          "o A\nf 1/1 2/2 3/3 4/4 5/5\n"
                                          "o B\nf 1/3 2/4 3/1 4/2\n"));
    // Pentagon -> 3 triangles, quad -> 2.
    ASSERT_EQ(m.triangles.size(), 5u);
    // 5 (position, uv) pairs in A and 4 different ones in B.
    EXPECT_EQ(m.positions.size(), 9u);
    // Convex polygons: the fan triangulation covers each exactly.
    // Shoelace: pentagon area 8, quad (0,0),(2,0),(3,2),(1,3) area 5.5.
    EXPECT_NEAR(surface_area(m), 8.0 + 5.5, 1e-6);
}

TEST_F(MeshObj, Errors) {
    expect_error(dir_ / "missing.obj", "the OBJ file does not exist");
    // A directory or a device is named as what it is (it read "not found").
    fs::create_directories(dir_ / "dir.obj");
    expect_error(dir_ / "dir.obj", "the OBJ file is a directory");
    expect_error(write("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"),
                 "vertex index 7 out of range");
    expect_error(write("bad_uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/5 3/1\n"),
                 "texcoord index 5 out of range");
    expect_error(write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "no triangles");
    expect_error(write("nan.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"),
                 "nan.obj:2: v field 1 \"1e999\" is not a finite decimal number");
    expect_error(write("line_face.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"), "no triangles");
}

// tinyobj read these as 0 (or "1,5" as 1) without a word; each is now an
// error naming the file, the line and the field.
TEST_F(MeshObj, NumbersAreReadStrictly) {
    const std::string tri = "v 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
    const struct {
        const char* first_line;
        const char* message;
    } cases[] = {
        {"v nan 0 0", "f.obj:1: v field 1 \"nan\" is not a finite decimal number"},
        {"v inf 0 0", "f.obj:1: v field 1 \"inf\" is not a finite decimal number"},
        {"v 0 abc 0", "f.obj:1: v field 2 \"abc\" is not a finite decimal number"},
        {"v 1,5 0 0", "f.obj:1: v field 1 \"1,5\" is not a finite decimal number"},
        {"v 0 0", "f.obj:1: v has 2 numbers (allowed: 3, 4 or 6)"},
        {"v 0 0 0 1 1", "f.obj:1: v has 5 numbers"},
        {"vt nan 0", "f.obj:1: vt field 1 \"nan\" is not a finite decimal number"},
        {"vn 0 0", "f.obj:1: vn has 2 numbers (allowed: 3)"},
        {"v 1e10 0 0", "position 0 = (1e+10, 0, 0) out of range"},
        {"v 0 0 0\nvt 1e16 0", "uv 0 = (1e+16, 0) out of range"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.first_line);
        expect_error(
            write("f.obj", std::string(c.first_line) + "\n" +
                               (std::string(c.first_line).starts_with("v ") ? "" : "v 0 0 0\n") +
                               tri),
            c.message);
    }
    // Valid forms stay valid: signs, exponents, w, colours, comments, CRLF.
    const TriangleMesh m =
        load_obj(write("ok.obj", "v +0.5e0 -0 0 1 # w\r\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.positions[0].x, 0.5f);
}

}  // namespace
}  // namespace glintlab
