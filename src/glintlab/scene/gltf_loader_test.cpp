#include "glintlab/scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kNoIndices = 0;
constexpr int kU8 = 5121, kU16 = 5123, kU32 = 5125, kFloat = 5126;

// The unit quad (0,0,0)-(1,1,0) facing +z, with uv = xy.
const std::vector<glm::vec3> kQuadPositions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

// A glTF document and its binary buffer, built field by field so each test
// can change one thing (index type, primitive mode, node transforms).
struct Asset {
    json doc;
    std::vector<uint8_t> bin;

    size_t add_view(const void* data, size_t bytes) {
        while (bin.size() % 4 != 0) bin.push_back(0);  // accessor alignment
        const size_t offset = bin.size();
        bin.resize(offset + bytes);
        std::memcpy(bin.data() + offset, data, bytes);
        doc["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
        return doc["bufferViews"].size() - 1;
    }
    size_t add_accessor(const void* data, size_t bytes, int component, const char* type,
                        size_t count) {
        const size_t view = add_view(data, bytes);
        doc["accessors"].push_back(
            {{"bufferView", view}, {"componentType", component}, {"type", type}, {"count", count}});
        return doc["accessors"].size() - 1;
    }
};

// One quad mesh, indexed with `index_type` (or expanded when kNoIndices).
Asset quad_asset(int index_type, int mode = 4) {
    std::vector<glm::vec3> positions = kQuadPositions;
    if (index_type == kNoIndices) {
        positions.clear();
        for (uint32_t i : kQuadIndices) positions.push_back(kQuadPositions[i]);
    }
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0, 0, 1));
    std::vector<glm::vec2> uvs;
    for (glm::vec3 p : positions) uvs.emplace_back(p.x, p.y);

    Asset a;
    a.doc = {{"asset", {{"version", "2.0"}}}};
    json prim = {{"mode", mode}, {"attributes", json::object()}};
    prim["attributes"]["POSITION"] =
        a.add_accessor(positions.data(), positions.size() * 12, kFloat, "VEC3", positions.size());
    prim["attributes"]["NORMAL"] =
        a.add_accessor(normals.data(), normals.size() * 12, kFloat, "VEC3", normals.size());
    prim["attributes"]["TEXCOORD_0"] =
        a.add_accessor(uvs.data(), uvs.size() * 8, kFloat, "VEC2", uvs.size());
    if (index_type != kNoIndices) {
        std::vector<uint8_t> bytes;
        const size_t size = index_type == kU8 ? 1 : index_type == kU16 ? 2 : 4;
        for (uint32_t i : kQuadIndices)
            for (size_t b = 0; b < size; ++b) bytes.push_back(static_cast<uint8_t>(i >> (8 * b)));
        prim["indices"] =
            a.add_accessor(bytes.data(), bytes.size(), index_type, "SCALAR", kQuadIndices.size());
    }
    a.doc["meshes"] = json::array({{{"name", "quad"}, {"primitives", json::array({prim})}}});
    return a;
}

// Node hierarchy used by the tests: scene 1 (the default) holds a parent
// translated by (1, 2, 3) whose child rotates 90 degrees about z and scales
// by 2; scene 0 holds an unrelated far-away instance that must be ignored.
glm::mat4 child_world() {
    return glm::translate(glm::mat4(1), glm::vec3(1, 2, 3)) *
           glm::rotate(glm::mat4(1), glm::radians(90.0f), glm::vec3(0, 0, 1)) *
           glm::scale(glm::mat4(1), glm::vec3(2));
}

void add_hierarchy(Asset& a, bool child_as_matrix) {
    json child = {{"mesh", 0}};
    if (child_as_matrix) {
        const glm::mat4 local = glm::rotate(glm::mat4(1), glm::radians(90.0f), glm::vec3(0, 0, 1)) *
                                glm::scale(glm::mat4(1), glm::vec3(2));
        const float* m = glm::value_ptr(local);  // column-major, like glTF
        child["matrix"] = std::vector<float>(m, m + 16);
    } else {
        const float h = std::sqrt(0.5f);
        child["rotation"] = {0, 0, h, h};  // (x, y, z, w): 90 degrees about z
        child["scale"] = {2, 2, 2};
    }
    a.doc["nodes"] = json::array({{{"translation", {1, 2, 3}}, {"children", {1}}},
                                  child,
                                  {{"translation", {100, 0, 0}}, {"mesh", 0}}});
    a.doc["scenes"] = json::array({{{"nodes", {2}}}, {{"nodes", {0}}}});
    a.doc["scene"] = 1;
}

std::string base64(const std::vector<uint8_t>& data) {
    static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < data.size(); i += 3) {
        uint32_t chunk = static_cast<uint32_t>(data[i]) << 16;
        if (i + 1 < data.size()) chunk |= static_cast<uint32_t>(data[i + 1]) << 8;
        if (i + 2 < data.size()) chunk |= data[i + 2];
        const size_t n = std::min<size_t>(3, data.size() - i);
        out += kDigits[(chunk >> 18) & 63];
        out += kDigits[(chunk >> 12) & 63];
        out += n > 1 ? kDigits[(chunk >> 6) & 63] : '=';
        out += n > 2 ? kDigits[chunk & 63] : '=';
    }
    return out;
}

class MeshGltf : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("glintlab_gltf_" + std::to_string(::getpid()) + "_" + info->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write_gltf(const std::string& name, Asset a) const {
        a.doc["buffers"] =
            json::array({{{"byteLength", a.bin.size()},
                          {"uri", "data:application/octet-stream;base64," + base64(a.bin)}}});
        const fs::path path = dir_ / name;
        std::ofstream(path) << a.doc.dump(1);
        return path;
    }

    // Binary glTF: 12-byte header, then a JSON chunk padded with spaces and a
    // BIN chunk padded with zeros, each to a multiple of 4 bytes.
    fs::path write_glb(const std::string& name, Asset a) const {
        a.doc["buffers"] = json::array({{{"byteLength", a.bin.size()}}});
        std::string text = a.doc.dump();
        while (text.size() % 4 != 0) text += ' ';
        std::vector<uint8_t> bin = a.bin;
        while (bin.size() % 4 != 0) bin.push_back(0);
        std::vector<uint8_t> out;
        auto put32 = [&out](uint32_t v) {
            for (int b = 0; b < 4; ++b) out.push_back(static_cast<uint8_t>(v >> (8 * b)));
        };
        put32(0x46546C67u);  // "glTF"
        put32(2);
        put32(static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
        put32(static_cast<uint32_t>(text.size()));
        put32(0x4E4F534Au);  // "JSON"
        out.insert(out.end(), text.begin(), text.end());
        put32(static_cast<uint32_t>(bin.size()));
        put32(0x004E4942u);  // "BIN\0"
        out.insert(out.end(), bin.begin(), bin.end());
        const fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary)
            .write(reinterpret_cast<const char*>(out.data()),
                   static_cast<std::streamsize>(out.size()));
        return path;
    }

    void expect_error(const fs::path& path, const std::string& fragment) const {
        try {
            load_gltf(path);
            ADD_FAILURE() << "no error for " << path;
        } catch (const Error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
            EXPECT_NE(message.find(fragment), std::string::npos) << message;
        }
    }

    fs::path dir_;
};

// The loaded quad must be the file's quad moved by child_world(): same
// indices, uvs unchanged, normals rotated to world.
void expect_transformed_quad(const TriangleMesh& m, bool indexed) {
    const glm::mat4 world = child_world();
    ASSERT_EQ(m.triangles.size(), 2u);
    ASSERT_TRUE(m.has_uvs() && m.has_normals());
    ASSERT_EQ(m.positions.size(), indexed ? 4u : 6u);
    for (size_t t = 0; t < 2; ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t file_index = indexed ? kQuadIndices[3 * t + k] : 3 * t + k;
            EXPECT_EQ(m.triangles[t][k], file_index);
            const glm::vec3 local = kQuadPositions[kQuadIndices[3 * t + k]];
            const glm::vec3 expected(world * glm::vec4(local, 1.0f));
            // Single-precision matrix products of values ~5: error ~1e-6.
            EXPECT_LE(glm::distance(m.positions[file_index], expected), 1e-5f);
            EXPECT_EQ(m.uvs[file_index], glm::vec2(local.x, local.y));
            EXPECT_LE(glm::distance(m.normals[file_index], glm::vec3(0, 0, 1)), 1e-6f);
        }
    EXPECT_NEAR(surface_area(m), 4.0, 1e-5);  // unit quad scaled by 2
}

TEST_F(MeshGltf, JsonWithDataUriAndTrsHierarchy) {
    for (int type : {kU8, kU16, kU32, kNoIndices}) {
        SCOPED_TRACE(type);
        Asset a = quad_asset(type);
        add_hierarchy(a, /*child_as_matrix=*/false);
        expect_transformed_quad(load_gltf(write_gltf("quad.gltf", a)), type != kNoIndices);
    }
}

TEST_F(MeshGltf, BinaryWithMatrixNode) {
    for (int type : {kU16, kNoIndices}) {
        SCOPED_TRACE(type);
        Asset a = quad_asset(type);
        add_hierarchy(a, /*child_as_matrix=*/true);
        expect_transformed_quad(load_gltf(write_glb("quad.glb", a)), type != kNoIndices);
    }
}

TEST_F(MeshGltf, MirroringNodeFlipsWinding) {
    Asset a = quad_asset(kU16);
    a.doc["nodes"] = json::array({{{"scale", {-1, 1, 1}}, {"mesh", 0}}});
    a.doc["scenes"] = json::array({{{"nodes", {0}}}});
    const TriangleMesh m = load_gltf(write_gltf("mirror.gltf", a));
    for (size_t t = 0; t < m.triangles.size(); ++t)
        EXPECT_GT(glm::dot(geometric_normal(m, t), m.normals[m.triangles[t].x]), 0.0f);
}

TEST_F(MeshGltf, Errors) {
    expect_error(dir_ / "missing.gltf", "not found");
    {
        std::ofstream(dir_ / "garbage.gltf") << "this is { not json";
        expect_error(dir_ / "garbage.gltf", "cannot parse");
    }
    {
        std::ofstream(dir_ / "garbage.glb", std::ios::binary) << "glTF\x02\x00\x00\x00junk";
        expect_error(dir_ / "garbage.glb", "cannot parse");
    }
    Asset points = quad_asset(kU16, /*mode=*/0);
    add_hierarchy(points, false);
    expect_error(write_gltf("points.gltf", points), "mode 0");

    Asset bad = quad_asset(kU8);
    add_hierarchy(bad, false);
    bad.bin[bad.doc["bufferViews"][3]["byteOffset"].get<size_t>() + 2] = 9;  // index 9 of 4
    expect_error(write_gltf("bad_index.gltf", bad), "out of range");

    Asset empty = quad_asset(kU16);
    empty.doc["nodes"] = json::array({json::object()});
    empty.doc["scenes"] = json::array({{{"nodes", {0}}}});
    expect_error(write_gltf("empty.gltf", empty), "no triangles");
}

}  // namespace
}  // namespace glintlab
