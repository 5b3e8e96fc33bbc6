#include "glintlab/scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <draco/metadata/geometry_metadata.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/memory_limit.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/renderer.h"
#include "glintlab/scene/draco_header.h"

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

    // paint.gltf: one quad whose primitive takes `material`, which reads
    // colour.png (written beside it) as texture 0.
    void write_paint_quad(const json& material) const;

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

// A 4x4 PNG: a colour checker in r and b, a ramp in g (codes, as data).
std::vector<uint8_t> write_test_png(const fs::path& path) {
    Image image(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            image.at(x, y) = glm::vec3((x + y) % 2 ? 0.8f : 0.1f, 0.1f + 0.2f * float(x),
                                       (x + y) % 2 ? 0.0f : 1.0f);
    write_png(image, path);
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

void MeshGltf::write_paint_quad(const json& material) const {
    write_test_png(dir_ / "colour.png");
    Asset a = quad_asset(kU16);
    a.doc["nodes"] = json::array({{{"mesh", 0}}});
    a.doc["meshes"][0]["primitives"][0]["material"] = 0;
    a.doc["materials"] = json::array({material});
    a.doc["textures"] = json::array({{{"source", 0}}});
    a.doc["images"] = json::array({{{"uri", "colour.png"}}});
    write_gltf("paint.gltf", a);
}

// Primitives split into one part per material; each part's uvs are the set
// its material's textures read; images in data uris are decoded, those in
// files named by path. A shape with its own "material" still gets one mesh
// of every primitive.
TEST_F(MeshGltf, PrimitivesSplitByMaterialWithTheirUvSetAndImages) {
    Asset a = quad_asset(kU16);
    add_hierarchy(a, /*child_as_matrix=*/false);
    json second = a.doc["meshes"][0]["primitives"][0];
    std::vector<glm::vec2> uv1;
    for (glm::vec3 p : kQuadPositions) uv1.emplace_back(2.0f * p.x, 3.0f * p.y);
    second["attributes"]["TEXCOORD_1"] =
        a.add_accessor(uv1.data(), uv1.size() * 8, kFloat, "VEC2", uv1.size());
    second["material"] = 1;
    a.doc["meshes"][0]["primitives"][0]["material"] = 0;
    a.doc["meshes"][0]["primitives"].push_back(second);
    const std::vector<uint8_t> png = write_test_png(dir_ / "colour.png");
    a.doc["materials"] = json::array(
        {{{"name", "A"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}},
         {{"name", "B"},
          {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}, {"texCoord", 1}}}}}}});
    a.doc["textures"] = json::array({{{"source", 0}}, {{"source", 1}}});
    a.doc["images"] =
        json::array({{{"uri", "colour.png"}}, {{"uri", "data:image/png;base64," + base64(png)}}});
    const fs::path path = write_gltf("two.gltf", a);
    const GltfScene g = load_gltf_scene(path);
    ASSERT_EQ(g.parts.size(), 2u);
    ASSERT_EQ(g.materials.size(), 2u);
    EXPECT_EQ(g.parts[0].material, 0);
    EXPECT_EQ(g.parts[1].material, 1);
    ASSERT_TRUE(g.parts[1].mesh.has_uvs());
    for (size_t i = 0; i < kQuadPositions.size(); ++i) {
        EXPECT_EQ(g.parts[0].mesh.uvs[i], glm::vec2(kQuadPositions[i]));
        EXPECT_EQ(g.parts[1].mesh.uvs[i], uv1[i]);
    }
    EXPECT_EQ(g.materials[0].block["base_color"]["texture"], (dir_ / "colour.png").string());
    const std::string embedded = fmt::format("<{} image 1>", path.string());
    EXPECT_EQ(g.materials[1].block["base_color"]["texture"], embedded);
    ASSERT_TRUE(g.images.contains(embedded));
    EXPECT_EQ(g.images.at(embedded)->width, 4);
    EXPECT_EQ(load_gltf(path).triangles.size(), 4u);
}

// The file's material renders exactly as the same material written in the
// scene: the translation is the scene format's own reading.
TEST_F(MeshGltf, FileMaterialsRenderAsTheSameMaterialWrittenInTheScene) {
    write_paint_quad(
        {{"name", "paint"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.8, 0.6, 0.9, 1.0}},
           {"baseColorTexture",
            {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {2, 2}}}}}}}},
           {"roughnessFactor", 0.8},
           {"metallicRoughnessTexture", {{"index", 0}}}}}});
    const json written = {
        {"name", "m"},
        {"type", "metallic_roughness"},
        {"base_color",
         {{"texture", "colour.png"}, {"scale", {0.8, 0.6, 0.9}}, {"uv_transform", {{"scale", 2}}}}},
        {"metallic", {{"texture", "colour.png"}, {"channel", "b"}}},
        {"roughness", {{"texture", "colour.png"}, {"channel", "g"}, {"scale", 0.8}, {"power", 2}}}};
    auto render = [&](bool file_material) {
        json shape = {{"type", "gltf"}, {"file", "paint.gltf"}};
        if (!file_material) shape["material"] = "m";
        const json scene = {
            {"film", {{"width", 24}, {"height", 24}}},
            {"camera", {{"eye", {0.5, 0.5, 2}}, {"target", {0.5, 0.5, 0}}, {"fov_deg", 40}}},
            {"render", {{"integrator", "path"}, {"spp", 2}, {"seed", 3}}},
            {"materials", file_material ? json::array() : json::array({written})},
            {"shapes", {shape}},
            {"lights",
             {{{"type", "directional"}, {"direction", {0.3, 0.2, 1}}, {"irradiance", 2}},
              {{"type", "environment"}, {"radiance", 0.2}}}}};
        return render_scene(parse_scene(scene, dir_ / "scene.json"), RenderOptions{1, true});
    };
    const Image from_file = render(true);
    // The shape's own material replaces the file's: a note says so.
    testing::internal::CaptureStderr();
    const Image from_scene = render(false);
    const std::string note = testing::internal::GetCapturedStderr();
    EXPECT_NE(note.find("the shape's material \"m\" replaces the file's 1 material (leave"),
              std::string::npos)
        << note;
    double sum = 0.0;
    for (size_t i = 0; i < from_file.pixels.size(); ++i) {
        EXPECT_EQ(from_file.pixels[i], from_scene.pixels[i]) << i;
        sum += double(from_file.pixels[i].x);
    }
    EXPECT_GT(sum, 0.0);
}

// A file material reading a uv set its primitive lacks: the error names the
// set and the option that gives the mesh uvs.
TEST_F(MeshGltf, AMissingUvSetIsNamedInTheError) {
    write_paint_quad(
        {{"name", "paint"},
         {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}}});
    const json scene = {
        {"film", {{"width", 8}, {"height", 8}}},
        {"camera", {{"eye", {0.5, 0.5, 2}}, {"target", {0.5, 0.5, 0}}, {"fov_deg", 40}}},
        {"shapes", json::array({{{"type", "gltf"}, {"file", "paint.gltf"}}})},
        {"lights", json::array({{{"type", "environment"}, {"radiance", 1}}})}};
    try {
        parse_scene(scene, dir_ / "scene.json");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("paint.gltf has no TEXCOORD_1, the set its material reads) (give "
                               "it one with \"uv\""),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("/shapes/0/file"), std::string::npos) << message;
    }
}

// glTF TANGENT: read, mapped by the node transform (a mirror flips w), and
// kept as the normal map's tangent space instead of generated ones.
TEST_F(MeshGltf, FileTangentsAreTransformedAndKeptForNormalMaps) {
    Asset a = quad_asset(kU16);
    const std::vector<glm::vec4> tangents(4, glm::vec4(0.0f, 1.0f, 0.0f, 0.5f));
    a.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] =
        a.add_accessor(tangents.data(), tangents.size() * 16, kFloat, "VEC4", tangents.size());
    a.doc["nodes"] = json::array({{{"mesh", 0}, {"scale", {-1, 1, 1}}}});
    write_gltf("tangents.gltf", a);
    const TriangleMesh m = load_gltf(dir_ / "tangents.gltf");
    ASSERT_EQ(m.tangents.size(), 4u);
    for (const glm::vec4& t : m.tangents) EXPECT_EQ(t, glm::vec4(0.0f, 1.0f, 0.0f, -1.0f));
    Image flat(2, 2, glm::vec3(0.5f, 0.5f, 1.0f));
    write_png(flat, dir_ / "flat.png");
    const json scene = {
        {"camera", {{"eye", {0, 0, 3}}, {"target", {0, 0, 0}}}},
        {"materials",
         {{{"name", "m"},
           {"type", "conductor"},
           {"normal_map", {{"texture", "flat.png"}, {"encoding", "unorm"}}}}}},
        {"shapes", {{{"type", "gltf"}, {"file", "tangents.gltf"}, {"material", "m"}}}}};
    const Scene s = parse_scene(scene, dir_ / "scene.json");
    const auto& mesh = std::get<TriangleMesh>(s.shapes[0].geometry);
    ASSERT_EQ(mesh.tangents.size(), 4u);
    EXPECT_EQ(mesh.tangents[0], glm::vec4(0.0f, 1.0f, 0.0f, -1.0f));  // not ∂p/∂u = (−1, 0, 0)
    json projected = scene;
    projected["shapes"][0]["uv"] = {{"projection", "planar"}, {"axis", "z"}};
    const Scene p = parse_scene(projected, dir_ / "scene.json");
    const auto& regenerated = std::get<TriangleMesh>(p.shapes[0].geometry);
    ASSERT_EQ(regenerated.tangents.size(), 4u);
    EXPECT_NEAR(std::abs(regenerated.tangents[0].x), 1.0f, 1e-5f);  // from the new uvs
}

// Generated tangents (glTF prescribes MikkTSpace where a file has none)
// against a file's own on a mesh that has both: a uv sphere of 64 x 32
// segments whose TANGENT is the analytic ∂p/∂u direction with glTF's sign
// (the bitangent w (n × t) up the image, against ∂p/∂v), as an exporter
// writes it for a smooth sphere. Away from the poles (|latitude| < 75°,
// where the rings' triangles are nearly isosceles) the angle-weighted mean
// of the triangles' ∂p/∂u matches the analytic direction to second order in
// the segment angle (5.6°): measured 0.02° at most; the bound 0.5° leaves
// room and is still far below one segment's turn.
TEST_F(MeshGltf, GeneratedTangentsEqualTheFilesOnAUvSphere) {
    const int nu = 64, nv = 32;
    const float pi = glm::pi<float>();
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec4> tangents;
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
            const float u = float(i) / nu, v = float(j) / nv;
            const float phi = 2.0f * pi * u, theta = pi * v;  // v = 0 at the north pole
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              -std::sin(theta) * std::sin(phi));
            positions.push_back(n);
            normals.push_back(n);
            uvs.emplace_back(u, v);
            const glm::vec3 dpdu = glm::normalize(glm::vec3(-std::sin(phi), 0.0f, -std::cos(phi)));
            const glm::vec3 dpdv(std::cos(theta) * std::cos(phi), -std::sin(theta),
                                 -std::cos(theta) * std::sin(phi));
            const float w = glm::dot(glm::cross(n, dpdu), -dpdv) > 0.0f ? 1.0f : -1.0f;
            tangents.emplace_back(dpdu, w);
        }
    std::vector<uint8_t> index_bytes;
    auto push = [&](uint32_t k) {
        for (int b = 0; b < 4; ++b) index_bytes.push_back(static_cast<uint8_t>(k >> (8 * b)));
    };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const uint32_t a = uint32_t(j * (nu + 1) + i), b = a + 1, c = a + uint32_t(nu + 1),
                           d = c + 1;
            // Counter-clockwise seen from outside.
            for (uint32_t k : {a, c, b, b, c, d}) push(k);
        }
    auto asset = [&](bool with_tangents) {
        Asset a;
        a.doc = {{"asset", {{"version", "2.0"}}}};
        json prim = {{"mode", 4}, {"attributes", json::object()}};
        prim["attributes"]["POSITION"] = a.add_accessor(positions.data(), positions.size() * 12,
                                                        kFloat, "VEC3", positions.size());
        prim["attributes"]["NORMAL"] =
            a.add_accessor(normals.data(), normals.size() * 12, kFloat, "VEC3", normals.size());
        prim["attributes"]["TEXCOORD_0"] =
            a.add_accessor(uvs.data(), uvs.size() * 8, kFloat, "VEC2", uvs.size());
        if (with_tangents)
            prim["attributes"]["TANGENT"] = a.add_accessor(tangents.data(), tangents.size() * 16,
                                                           kFloat, "VEC4", tangents.size());
        prim["indices"] = a.add_accessor(index_bytes.data(), index_bytes.size(), kU32, "SCALAR",
                                         index_bytes.size() / 4);
        a.doc["meshes"] = json::array({{{"name", "sphere"}, {"primitives", json::array({prim})}}});
        a.doc["nodes"] = json::array({{{"mesh", 0}}});
        return a;
    };
    write_gltf("with.gltf", asset(true));
    write_gltf("without.gltf", asset(false));
    Image flat(2, 2, glm::vec3(0.5f, 0.5f, 1.0f));
    write_png(flat, dir_ / "flat.png");
    auto mesh_tangents = [&](const char* file) {
        const json scene = {{"camera", {{"eye", {0, 0, 3}}, {"target", {0, 0, 0}}}},
                            {"materials",
                             {{{"name", "m"},
                               {"type", "conductor"},
                               {"normal_map", {{"texture", "flat.png"}, {"encoding", "unorm"}}}}}},
                            {"shapes", {{{"type", "gltf"}, {"file", file}, {"material", "m"}}}}};
        const Scene s = parse_scene(scene, dir_ / "scene.json");
        return std::get<TriangleMesh>(s.shapes[0].geometry).tangents;
    };
    const std::vector<glm::vec4> from_file = mesh_tangents("with.gltf");
    const std::vector<glm::vec4> generated = mesh_tangents("without.gltf");
    ASSERT_EQ(from_file.size(), positions.size());
    ASSERT_EQ(generated.size(), positions.size());
    double worst_deg = 0.0;
    int compared = 0;
    for (size_t k = 0; k < positions.size(); ++k) {
        // The seam's vertices (u = 0 and 1) see triangles on one side only;
        // MikkTSpace, which welds vertices only where their uvs agree too,
        // averages them one-sidedly as well (up to 2.7° from the analytic
        // direction here), so the analytic file tangent is no reference there.
        if (std::abs(positions[k].y) > std::sin(glm::radians(75.0f)) || uvs[k].x == 0.0f ||
            uvs[k].x == 1.0f)
            continue;
        const glm::vec3 a = glm::vec3(from_file[k]), b = glm::vec3(generated[k]);
        EXPECT_EQ(from_file[k].w, generated[k].w) << k;
        const double dd = double(glm::degrees(
            std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f))));
        worst_deg = std::max(worst_deg, dd);
        ++compared;
    }
    RecordProperty("worst_deg", std::to_string(worst_deg));
    EXPECT_GT(compared, 1000);
    EXPECT_LT(worst_deg, 0.5) << compared << " vertices";
}

// Hostile material data: each is an error naming the file and what is wrong,
// never a crash or a silently untextured material.
TEST_F(MeshGltf, BadMaterialTexturesAndImagesAreErrors) {
    auto with_texture = [&](const json& images, const json& textures, int index) {
        Asset a = quad_asset(kU16);
        a.doc["nodes"] = json::array({{{"mesh", 0}}});
        a.doc["meshes"][0]["primitives"][0]["material"] = 0;
        a.doc["materials"] =
            json::array({{{"name", "paint"},
                          {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", index}}}}}}});
        if (!textures.is_null()) a.doc["textures"] = textures;
        if (!images.is_null()) a.doc["images"] = images;
        return a;
    };
    auto error = [&](const Asset& a) {
        const fs::path path = write_gltf("bad.gltf", a);
        try {
            const json scene = {{"camera", {{"eye", {0, 0, 3}}, {"target", {0, 0, 0}}}},
                                {"shapes", {{{"type", "gltf"}, {"file", "bad.gltf"}}}}};
            parse_scene(scene, dir_ / "scene.json");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string index = error(with_texture(nullptr, nullptr, 5));
    EXPECT_NE(index.find("bad.gltf: material \"paint\": baseColorTexture names texture 5, out "
                         "of range [0, 0)"),
              std::string::npos)
        << index;
    const std::vector<uint8_t> garbage = {'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'a', 'g'};
    const std::string decode =
        error(with_texture(json::array({{{"uri", "data:image/png;base64," + base64(garbage)}}}),
                           json::array({{{"source", 0}}}), 0));
    EXPECT_NE(decode.find("bad.gltf image 0>"), std::string::npos) << decode;
    EXPECT_NE(decode.find("neither the PNG signature nor the JPEG"), std::string::npos) << decode;
    const std::string missing = error(
        with_texture(json::array({{{"uri", "nowhere.png"}}}), json::array({{{"source", 0}}}), 0));
    EXPECT_NE(missing.find("nowhere.png"), std::string::npos) << missing;
    EXPECT_NE(missing.find("not found"), std::string::npos) << missing;
    // An image in a buffer view past the end of its buffer.
    Asset past = with_texture(json::array({{{"bufferView", 0}, {"mimeType", "image/png"}}}),
                              json::array({{{"source", 0}}}), 0);
    past.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 1 << 20}});
    past.doc["images"][0]["bufferView"] = past.doc["bufferViews"].size() - 1;
    const std::string view = error(past);
    EXPECT_NE(view.find("bad.gltf"), std::string::npos) << view;
    EXPECT_EQ(view.find("no error"), std::string::npos) << view;
}

TEST_F(MeshGltf, MaterialOverridesNameTheFilesMaterials) {
    Asset a = quad_asset(kU16);
    a.doc["nodes"] = json::array({{{"mesh", 0}}});
    a.doc["meshes"][0]["primitives"][0]["material"] = 0;
    a.doc["materials"] = json::array({{{"name", "paint"}}});
    write_gltf("paint.gltf", a);
    auto error = [&](const json& shape) {
        const json scene = {{"camera", {{"eye", {0, 0, 3}}, {"target", {0, 0, 0}}}},
                            {"materials", {{{"name", "m"}, {"type", "diffuse"}}}},
                            {"shapes", {shape}}};
        try {
            parse_scene(scene, dir_ / "scene.json");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const std::string unknown = error({{"type", "gltf"},
                                       {"file", "paint.gltf"},
                                       {"material_overrides", {{"Paint", {{"type", "diffuse"}}}}}});
    EXPECT_NE(unknown.find("/shapes/0/material_overrides/Paint"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("has no material named \"Paint\" (its materials: \"paint\")"),
              std::string::npos)
        << unknown;
    const std::string both = error({{"type", "gltf"},
                                    {"file", "paint.gltf"},
                                    {"material", "m"},
                                    {"material_overrides", {{"paint", {{"type", "diffuse"}}}}}});
    EXPECT_NE(both.find("\"material\" replaces them all"), std::string::npos) << both;
    const std::string bad = error({{"type", "gltf"},
                                   {"file", "paint.gltf"},
                                   {"material_overrides", {{"paint", {{"type", "velvet"}}}}}});
    EXPECT_NE(bad.find("/shapes/0/material_overrides/paint/type"), std::string::npos) << bad;
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

// A 60,000-deep chain of nodes (each translating by 1e-4 along x) with the
// quad at the leaf. A recursive walk would overflow the stack; the iterative
// one must place the quad at x + 60000·1e-4 = x + 6.
TEST_F(MeshGltf, DeepNodeChainLoads) {
    constexpr int kDepth = 60000;
    Asset a = quad_asset(kU16);
    json nodes = json::array();
    for (int i = 0; i < kDepth; ++i) {
        json node = {{"translation", {1e-4, 0, 0}}};
        if (i + 1 < kDepth)
            node["children"] = {i + 1};
        else
            node["mesh"] = 0;
        nodes.push_back(std::move(node));
    }
    a.doc["nodes"] = std::move(nodes);
    a.doc["scenes"] = json::array({{{"nodes", {0}}}});
    const TriangleMesh m = load_gltf(write_gltf("deep.gltf", a));
    ASSERT_EQ(m.positions.size(), 4u);
    for (size_t i = 0; i < 4; ++i) {
        // The sum of 60000 steps of 1e-4 in double precision is exact to
        // ~1e-12; the float result carries ~1 ulp of 6 (5e-7).
        EXPECT_NEAR(m.positions[i].x, kQuadPositions[i].x + 6.0f, 2e-6f);
        EXPECT_EQ(m.positions[i].y, kQuadPositions[i].y);
    }
}

// A node graph with a cycle is not a forest: the error names the file and a
// node of the cycle, both when the scene's root lies on the cycle and when
// there is no scene (then every node is a child, none is a root). A node
// with two parents (which a path into a cycle needs, and which would
// instance subtrees once per path, exponentially many in a chain) and an
// out-of-range child are errors too.
TEST_F(MeshGltf, NodeCycleIsAnError) {
    Asset a = quad_asset(kU16);
    a.doc["nodes"] =
        json::array({{{"children", {1}}}, {{"children", {2}}, {"mesh", 0}}, {{"children", {0}}}});
    a.doc["scenes"] = json::array({{{"nodes", {0}}}});
    expect_error(write_gltf("cycle.gltf", a), "cycle");
    expect_error(write_gltf("cycle.gltf", a), "node 0 is its own ancestor");
    a.doc.erase("scenes");
    expect_error(write_gltf("cycle_noscene.gltf", a), "cycle");
    a.doc["nodes"][2]["children"] = {1};  // 0 → 1 → 2 → 1
    a.doc["scenes"] = json::array({{{"nodes", {0}}}});
    expect_error(write_gltf("two_parents.gltf", a), "node 1 is a child of both node 0 and node 2");
    a.doc["nodes"][2]["children"] = {7};
    expect_error(write_gltf("bad_child.gltf", a), "node 2 has child index 7 out of range");
}

// --- KHR_draco_mesh_compression ---------------------------------------------

// A wavy 12x12-vertex grid over [-1, 1]² (z = 0.2 sin·cos), with analytic
// normals and uvs = 1.5·(x + 1, y + 1) ∈ [0, 3]².
struct SourceMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::uvec3> triangles;
};

SourceMesh wavy_grid() {
    constexpr int n = 12;
    SourceMesh m;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = -1.0f + 2.0f * i / (n - 1), y = -1.0f + 2.0f * j / (n - 1);
            const float z = 0.2f * std::sin(3.0f * x) * std::cos(2.0f * y);
            m.positions.emplace_back(x, y, z);
            const float dzdx = 0.6f * std::cos(3.0f * x) * std::cos(2.0f * y);
            const float dzdy = -0.4f * std::sin(3.0f * x) * std::sin(2.0f * y);
            m.normals.push_back(glm::normalize(glm::vec3(-dzdx, -dzdy, 1.0f)));
            m.uvs.emplace_back(1.5f * (x + 1.0f), 1.5f * (y + 1.0f));
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const unsigned a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
            m.triangles.emplace_back(a, b, c);
            m.triangles.emplace_back(a, c, d);
        }
    return m;
}

constexpr int kPositionBits = 14, kUvBits = 12, kNormalBits = 10;

// Encodes `m` with Draco's encoder (edgebreaker, which reorders points and
// faces, unless `sequential`) and returns the bytes and the unique ids of
// position/normal/uv; `metadata` adds geometry and attribute metadata with
// a nested sub-metadata (the stream's metadata section).
std::vector<uint8_t> draco_encode(const SourceMesh& m, int ids[3], bool sequential = false,
                                  bool metadata = false) {
    draco::Mesh dm;
    const auto n = static_cast<uint32_t>(m.positions.size());
    dm.set_num_points(n);
    auto add = [&](draco::GeometryAttribute::Type type, int comps, const float* data) {
        draco::GeometryAttribute ga;
        ga.Init(type, nullptr, static_cast<uint8_t>(comps), draco::DT_FLOAT32, false,
                sizeof(float) * comps, 0);
        const int att = dm.AddAttribute(ga, /*identity_mapping=*/true, n);
        for (uint32_t i = 0; i < n; ++i)
            dm.attribute(att)->SetAttributeValue(draco::AttributeValueIndex(i), data + comps * i);
        return static_cast<int>(dm.attribute(att)->unique_id());
    };
    ids[0] = add(draco::GeometryAttribute::POSITION, 3, &m.positions[0].x);
    ids[1] = add(draco::GeometryAttribute::NORMAL, 3, &m.normals[0].x);
    ids[2] = add(draco::GeometryAttribute::TEX_COORD, 2, &m.uvs[0].x);
    for (glm::uvec3 t : m.triangles)
        dm.AddFace({draco::PointIndex(t.x), draco::PointIndex(t.y), draco::PointIndex(t.z)});
    if (metadata) {
        auto geometry = std::make_unique<draco::GeometryMetadata>();
        geometry->AddEntryString("name", "wavy grid");
        auto sub = std::make_unique<draco::Metadata>();
        sub->AddEntryInt("level", 2);
        auto subsub = std::make_unique<draco::Metadata>();
        subsub->AddEntryString("note", std::string(300, 'x'));  // a 2-byte varint length
        sub->AddSubMetadata("deeper", std::move(subsub));
        geometry->AddSubMetadata("group", std::move(sub));
        dm.AddMetadata(std::move(geometry));
        auto uv = std::make_unique<draco::AttributeMetadata>();
        uv->AddEntryString("channel", "uv0");
        dm.AddAttributeMetadata(dm.GetNamedAttributeId(draco::GeometryAttribute::TEX_COORD),
                                std::move(uv));
    }
    draco::Encoder encoder;
    if (sequential) encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, kPositionBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, kUvBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, kNormalBits);
    draco::EncoderBuffer buffer;
    const draco::Status status = encoder.EncodeMeshToBuffer(dm, &buffer);
    EXPECT_TRUE(status.ok()) << status.error_msg_string();
    return {reinterpret_cast<const uint8_t*>(buffer.data()),
            reinterpret_cast<const uint8_t*>(buffer.data()) + buffer.size()};
}

// A glTF whose one primitive is Draco-compressed: accessors without
// bufferViews (count and type only, as the extension prescribes).
Asset draco_asset(const SourceMesh& m) {
    int ids[3];
    const std::vector<uint8_t> bytes = draco_encode(m, ids);
    Asset a;
    a.doc = {{"asset", {{"version", "2.0"}}},
             {"extensionsUsed", {"KHR_draco_mesh_compression"}},
             {"extensionsRequired", {"KHR_draco_mesh_compression"}}};
    const size_t view = a.add_view(bytes.data(), bytes.size());
    const size_t n = m.positions.size();
    a.doc["accessors"] = json::array({
        {{"componentType", kFloat}, {"type", "VEC3"}, {"count", n}},
        {{"componentType", kFloat}, {"type", "VEC3"}, {"count", n}},
        {{"componentType", kFloat}, {"type", "VEC2"}, {"count", n}},
        {{"componentType", kU32}, {"type", "SCALAR"}, {"count", 3 * m.triangles.size()}},
    });
    json prim = {
        {"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
        {"indices", 3},
        {"extensions",
         {{"KHR_draco_mesh_compression",
           {{"bufferView", view},
            {"attributes", {{"POSITION", ids[0]}, {"NORMAL", ids[1]}, {"TEXCOORD_0", ids[2]}}}}}}}};
    a.doc["meshes"] = json::array({{{"name", "wavy"}, {"primitives", json::array({prim})}}});
    a.doc["nodes"] = json::array({{{"mesh", 0}}});
    a.doc["scenes"] = json::array({{{"nodes", {0}}}});
    return a;
}

// The decoded mesh must be the source mesh up to Draco's quantisation and
// its reordering of points and faces (and rotation of a face's corners,
// orientation kept). Tolerances from the quantisation: a q-bit attribute is
// quantised on a uniform grid of step range/(2^q − 1) over its bounding box
// (range = the largest extent over components), so each component is off by
// at most half a step, plus float rounding (≤ 1e-6 here). Positions: range 2
// (x, y ∈ [-1, 1]), q = 14 → 6.1e-5. Uvs: range 3, q = 12 → 3.7e-4. Normals
// are octahedrally quantised: a grid of step 2/(2^q − 1) on the square
// [-1, 1]², mapped to the sphere by normalising (s, t, 1 − |s| − |t|),
// whose length is ≥ 1/√3; half a step in s and t moves that vector by at
// most √6/2 steps, and normalising stretches by ≤ √3: angle ≤ 2.13 steps =
// 4.2e-3 rad for q = 10.
void expect_matches_source(const TriangleMesh& got, const SourceMesh& src) {
    const float pos_tol = 0.5f * 2.0f / ((1 << kPositionBits) - 1) + 1e-6f;
    const float uv_tol = 0.5f * 3.0f / ((1 << kUvBits) - 1) + 1e-6f;
    const float normal_angle = 2.13f * 2.0f / ((1 << kNormalBits) - 1);
    ASSERT_EQ(got.triangles.size(), src.triangles.size());
    ASSERT_TRUE(got.has_normals() && got.has_uvs());
    std::vector<int> matched(src.triangles.size(), 0);
    for (size_t t = 0; t < got.triangles.size(); ++t) {
        const glm::uvec3 g = got.triangles[t];
        const glm::vec3 centroid =
            (got.positions[g.x] + got.positions[g.y] + got.positions[g.z]) / 3.0f;
        size_t best = 0;
        float best_d = 1e30f;
        for (size_t s = 0; s < src.triangles.size(); ++s) {
            const glm::uvec3 v = src.triangles[s];
            const float d = glm::distance(
                centroid, (src.positions[v.x] + src.positions[v.y] + src.positions[v.z]) / 3.0f);
            if (d < best_d) best_d = d, best = s;
        }
        ++matched[best];
        const glm::uvec3 v = src.triangles[best];
        int rotation = -1;
        for (int r = 0; r < 3; ++r)
            if (glm::distance(got.positions[g[0]], src.positions[v[r]]) < 2.0f * pos_tol)
                rotation = r;
        ASSERT_GE(rotation, 0) << "triangle " << t;
        for (int k = 0; k < 3; ++k) {
            const unsigned gi = g[k], si = v[(k + rotation) % 3];
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(got.positions[gi][c], src.positions[si][c], pos_tol);
            for (int c = 0; c < 2; ++c) EXPECT_NEAR(got.uvs[gi][c], src.uvs[si][c], uv_tol);
            const float cos_angle = glm::dot(glm::normalize(got.normals[gi]), src.normals[si]);
            EXPECT_GE(cos_angle, std::cos(normal_angle));
        }
    }
    for (size_t s = 0; s < matched.size(); ++s) EXPECT_EQ(matched[s], 1) << "source " << s;
}

TEST_F(MeshGltf, DracoCompressedPrimitiveDecodes) {
    const SourceMesh src = wavy_grid();
    const Asset a = draco_asset(src);
    {
        SCOPED_TRACE("gltf");
        expect_matches_source(load_gltf(write_gltf("draco.gltf", a)), src);
    }
    {
        SCOPED_TRACE("glb");
        expect_matches_source(load_gltf(write_glb("draco.glb", a)), src);
    }
}

// The sizes read from a Draco stream's header before decoding are the
// mesh's, for both encodings and with a metadata section to walk; a stream
// declaring 2.4e8 faces in 856 bytes (the glTF fuzzer's input, which made
// Draco allocate 2.9 GB) is refused by the memory limit before Draco runs.
TEST_F(MeshGltf, DracoDeclaredSizesAreReadAndBoundedBeforeDecoding) {
    const SourceMesh src = wavy_grid();
    for (bool sequential : {false, true})
        for (bool metadata : {false, true}) {
            SCOPED_TRACE(::testing::Message()
                         << "sequential " << sequential << " metadata " << metadata);
            int ids[3];
            const std::vector<uint8_t> bytes = draco_encode(src, ids, sequential, metadata);
            ASSERT_EQ(bytes[10] & 0x80, metadata ? 0x80 : 0)
                << "the metadata flag (bit 15 of the flags)";
            const auto sizes =
                read_draco_mesh_sizes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
            ASSERT_TRUE(sizes.has_value());
            EXPECT_EQ(sizes->edgebreaker, !sequential);
            EXPECT_EQ(sizes->faces, src.triangles.size());
            EXPECT_EQ(sizes->vertices, src.positions.size());
        }
    const std::filesystem::path input = std::filesystem::path(GLINTLAB_SOURCE_DIR) /
                                        "fuzz/regressions/gltf/draco_edgebreaker_faces_2e8.glb";
    set_memory_limit(uint64_t(1) << 30);
    try {
        load_gltf(input);
        ADD_FAILURE() << "the declared 2.4e8 faces were decoded";
    } catch (const Error& e) {
        const std::string message = e.what();
        for (const char* needle : {"draco_edgebreaker_faces_2e8.glb", "KHR_draco_mesh_compression",
                                   "decoding the Draco mesh (Edgebreaker encoding) needs about",
                                   "Draco mesh of 242974574 faces"})
            EXPECT_NE(message.find(needle), std::string::npos) << message;
    }
    set_memory_limit(std::nullopt);
}

// The same grid uncompressed, for the render comparison.
Asset plain_asset(const SourceMesh& m) {
    Asset a;
    a.doc = {{"asset", {{"version", "2.0"}}}};
    const size_t n = m.positions.size();
    std::vector<uint32_t> indices;
    for (glm::uvec3 t : m.triangles) indices.insert(indices.end(), {t.x, t.y, t.z});
    json prim = {{"attributes", json::object()}};
    prim["attributes"]["POSITION"] = a.add_accessor(m.positions.data(), n * 12, kFloat, "VEC3", n);
    prim["attributes"]["NORMAL"] = a.add_accessor(m.normals.data(), n * 12, kFloat, "VEC3", n);
    prim["attributes"]["TEXCOORD_0"] = a.add_accessor(m.uvs.data(), n * 8, kFloat, "VEC2", n);
    prim["indices"] =
        a.add_accessor(indices.data(), indices.size() * 4, kU32, "SCALAR", indices.size());
    a.doc["meshes"] = json::array({{{"name", "wavy"}, {"primitives", json::array({prim})}}});
    a.doc["nodes"] = json::array({{{"mesh", 0}}});
    a.doc["scenes"] = json::array({{{"nodes", {0}}}});
    return a;
}

// Rendered, the Draco mesh equals the uncompressed one within what the
// quantisation allows. Setup: orthographic view straight down (−z) on the
// interior of the grid (no silhouette), Lambertian albedo 0.5 lit by a
// directional light of irradiance 1 along +z (no self-shadowing: the
// slopes stay below 45°), direct integrator, 1 spp at pixel centres:
// L = (0.5/π)·cos(n, z) is deterministic. cos moves by at most the normal
// error: 4.2e-3 rad of octahedral quantisation plus the interpolated
// normal's change over the ≤ 6.1e-5 position error (its gradient is
// bounded by the height's Hessian, |z_xx| + |z_xy| ≤ 1.8 + 1.2 = 3 rad per
// unit: 1.8e-4 rad): |ΔL| ≤ 0.5/π · 4.4e-3 = 7e-4.
TEST_F(MeshGltf, DracoRenderMatchesUncompressed) {
    const SourceMesh src = wavy_grid();
    write_gltf("plain.gltf", plain_asset(src));
    write_glb("draco.glb", draco_asset(src));
    auto render = [&](const std::string& file) {
        const json scene = {
            {"film", {{"width", 24}, {"height", 24}}},
            {"camera",
             {{"type", "orthographic"},
              {"eye", {0, 0, 5}},
              {"target", {0, 0, 0}},
              {"up", {0, 1, 0}},
              {"height", 1.6}}},
            {"render", {{"integrator", "direct"}, {"spp", 1}}},
            {"materials", {{{"name", "clay"}, {"type", "diffuse"}, {"albedo", 0.5}}}},
            {"shapes", {{{"type", "gltf"}, {"file", file}, {"material", "clay"}}}},
            {"lights", {{{"type", "directional"}, {"direction", {0, 0, 1}}, {"irradiance", 1}}}}};
        return render_scene(parse_scene(scene, dir_ / "scene.json"), RenderOptions{1, true});
    };
    const Image plain = render("plain.gltf"), draco = render("draco.glb");
    ASSERT_EQ(plain.pixels.size(), draco.pixels.size());
    const float bound = 0.5f / glm::pi<float>() * 4.4e-3f;
    float worst = 0.0f, brightest = 0.0f;
    for (size_t i = 0; i < plain.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, std::abs(plain.pixels[i][c] - draco.pixels[i][c]));
            brightest = std::max(brightest, plain.pixels[i][c]);
        }
    EXPECT_LE(worst, bound);
    EXPECT_GT(brightest, 0.1f);  // the grid is lit and in view
}

TEST_F(MeshGltf, DracoAndExtensionErrors) {
    const SourceMesh src = wavy_grid();
    Asset unknown_id = draco_asset(src);
    unknown_id.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]
                  ["attributes"]["TEXCOORD_0"] = 42;
    expect_error(write_gltf("draco_id.gltf", unknown_id), "no attribute with id 42");

    Asset bad_view = draco_asset(src);
    bad_view.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]
                ["bufferView"] = 9;
    expect_error(write_gltf("draco_view.gltf", bad_view), "bufferView 9 out of range");

    Asset corrupt = draco_asset(src);
    for (size_t i = 0; i < 16; ++i) corrupt.bin[i] = 0xff;  // the Draco header
    expect_error(write_gltf("draco_corrupt.gltf", corrupt), "Draco cannot decode");

    Asset count = draco_asset(src);
    count.doc["accessors"][0]["count"] = 3;
    expect_error(write_gltf("draco_count.gltf", count), "POSITION accessor count 3");

    Asset required = quad_asset(kU16);
    add_hierarchy(required, false);
    required.doc["extensionsRequired"] = {"KHR_materials_clearcoat", "EXT_meshopt_compression"};
    expect_error(write_gltf("meshopt.gltf", required), "\"EXT_meshopt_compression\"");
    // Material extensions alone do not change the geometry: accepted.
    required.doc["extensionsRequired"] = {"KHR_materials_clearcoat"};
    EXPECT_EQ(load_gltf(write_gltf("clearcoat.gltf", required)).triangles.size(), 2u);
}

// extras nested 20 000 deep crashed inside tinygltf's recursive JSON walk
// (from the CLI, and the Python interpreter with it); the loader refuses
// the nesting before tinygltf parses, for .gltf and for a GLB's JSON chunk.
TEST_F(MeshGltf, DeepExtrasAreAnErrorNotACrash) {
    Asset a = quad_asset(kU16);
    add_hierarchy(a, false);
    for (const char* name : {"deep.gltf", "deep.glb"}) {
        SCOPED_TRACE(name);
        const bool binary = std::string_view(name).ends_with(".glb");
        a.doc["extras"] = "DEEP";
        const std::filesystem::path file = binary ? write_glb(name, a) : write_gltf(name, a);
        std::string bytes;
        {
            std::ifstream in(file, std::ios::binary);
            bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
        const size_t at = bytes.find("\"DEEP\"");
        ASSERT_NE(at, std::string::npos);
        std::string deep = std::string(20000, '[') + std::string(20000, ']');
        if (binary) deep += std::string((4 - (deep.size() - 6) % 4) % 4, ' ');
        bytes.replace(at, 6, deep);
        if (binary) {  // the GLB's total and JSON chunk lengths grow by the same amount
            const auto grow = static_cast<uint32_t>(deep.size() - 6);
            for (size_t offset : {size_t(8), size_t(12)}) {
                uint32_t v;
                std::memcpy(&v, bytes.data() + offset, 4);
                v += grow;
                std::memcpy(bytes.data() + offset, &v, 4);
            }
        }
        std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
        expect_error(file, "20001 levels deep (at most 256 are read)");
    }
}

TEST_F(MeshGltf, Errors) {
    expect_error(dir_ / "missing.gltf", "the glTF file does not exist");
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
