#include "glintlab/fuzz/fuzz_entries.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

// The JPEG seed's writer (glintlab reads JPEG but writes none; static: no
// clash with core/image_stb.cpp's copy).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/core/memory_limit.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/scene/gltf_loader.h"
#include "glintlab/scene/obj_loader.h"

namespace glintlab::fuzz {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// --- Checks of loaded results ------------------------------------------------

void check_mesh(const TriangleMesh& mesh, const std::string& what) {
    try {
        mesh.validate(what);
    } catch (const Error& e) {
        throw InvariantViolation(fmt::format("accepted mesh is invalid: {}", e.what()));
    }
}

void check_image(const Image& image, const std::string& what) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != size_t(image.width) * size_t(image.height))
        throw InvariantViolation(fmt::format("{}: accepted image claims {}x{} but holds {} pixels",
                                             what, image.width, image.height, image.pixels.size()));
    for (const glm::vec3& p : image.pixels)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw InvariantViolation(
                fmt::format("{}: accepted image has a non-finite pixel", what));
}

void check_scene(const Scene& scene) {
    for (const Shape& shape : scene.shapes)
        if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry))
            check_mesh(*mesh, shape.name);
    for (const Light& light : scene.lights) {
        const auto* env = std::get_if<EnvironmentLight>(&light);
        if (!env) continue;
        check_image(env->map->image(), "environment map");
        // The sampling distribution built from the map must give finite
        // radiance and a finite, non-negative density.
        glm::vec3 dir;
        float pdf = 0.0f;
        const glm::vec3 radiance = env->map->sample(glm::vec2(0.3f, 0.7f), &dir, &pdf);
        if (!std::isfinite(radiance.x + radiance.y + radiance.z) || !std::isfinite(pdf) ||
            pdf < 0.0f)
            throw InvariantViolation("environment map sample is not finite");
    }
}

// --- Scratch directory and assets ---------------------------------------------

std::string bytes_of(const void* data, size_t size) {
    return std::string(static_cast<const char*>(data), size);
}

void write_file(const fs::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) fail("{}: cannot write fuzzing file", path.string());
}

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// A unit quad in the xz plane with normals and uvs (4 vertices, 2 triangles).
struct Quad {
    float positions[12] = {-1, 0, 1, 1, 0, 1, 1, 0, -1, -1, 0, -1};
    float normals[12] = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    float uvs[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
};

std::string obj_quad() {
    return "# quad with positions, uvs and normals\n"
           "v -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\n"
           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
           "vn 0 1 0\n"
           "o quad\nf 1/1/1 2/2/1 3/3/1 4/4/1\n";
}

std::string obj_polygons() {
    return "# a pentagon without uvs or normals, relative indices, two groups\n"
           "v 0 0 0\nv 1 0 0\nv 1.5 1 0\nv 0.5 2 0\nv -0.5 1 0\n"
           "g a\nf -5 -4 -3 -2 -1\n"
           "g b\ns 1\nf 1 2 3\n";
}

// The glTF document of a quad whose buffer is `uri` (a data URI or a GLB's
// BIN chunk when empty), under a TRS node below a matrix node.
json gltf_quad_document(const std::string& uri, size_t buffer_size) {
    json buffer = {{"byteLength", buffer_size}};
    if (!uri.empty()) buffer["uri"] = uri;
    return {
        {"asset", {{"version", "2.0"}}},
        {"buffers", json::array({buffer})},
        {"bufferViews", json::array({
                            {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
                            {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 48}},
                            {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 32}},
                            {{"buffer", 0}, {"byteOffset", 128}, {"byteLength", 12}},
                        })},
        {"accessors",
         json::array({
             {{"bufferView", 0},
              {"componentType", 5126},
              {"type", "VEC3"},
              {"count", 4},
              {"min", {-1, 0, -1}},
              {"max", {1, 0, 1}}},
             {{"bufferView", 1}, {"componentType", 5126}, {"type", "VEC3"}, {"count", 4}},
             {{"bufferView", 2}, {"componentType", 5126}, {"type", "VEC2"}, {"count", 4}},
             {{"bufferView", 3}, {"componentType", 5123}, {"type", "SCALAR"}, {"count", 6}},
         })},
        {"meshes",
         json::array(
             {{{"primitives",
                json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                              {"indices", 3},
                              {"mode", 4}}})}}})},
        {"nodes", json::array({{{"children", {1}},
                                {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, 0, 1}}},
                               {{"mesh", 0},
                                {"translation", {0, 0.25, 0}},
                                {"rotation", {0, 0.3826834, 0, 0.9238795}},
                                {"scale", {2, 2, 2}}}})},
        {"scenes", json::array({{{"nodes", {0}}}})},
        {"scene", 0},
    };
}

std::string quad_buffer() {
    const Quad q;
    std::string b;
    b += bytes_of(q.positions, sizeof q.positions);
    b += bytes_of(q.normals, sizeof q.normals);
    b += bytes_of(q.uvs, sizeof q.uvs);
    b += bytes_of(q.indices, sizeof q.indices);
    return b;
}

std::string base64(const std::string& data) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < data.size(); i += 3) {
        const size_t n = std::min<size_t>(3, data.size() - i);
        uint32_t chunk = uint32_t(uint8_t(data[i])) << 16;
        if (n > 1) chunk |= uint32_t(uint8_t(data[i + 1])) << 8;
        if (n > 2) chunk |= uint8_t(data[i + 2]);
        out += digits[(chunk >> 18) & 63];
        out += digits[(chunk >> 12) & 63];
        out += n > 1 ? digits[(chunk >> 6) & 63] : '=';
        out += n > 2 ? digits[chunk & 63] : '=';
    }
    return out;
}

std::string gltf_quad_json() {
    const std::string buffer = quad_buffer();
    return gltf_quad_document("data:application/octet-stream;base64," + base64(buffer),
                              buffer.size())
        .dump(1);
}

void put32(std::string& out, uint32_t v) {
    for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((v >> (8 * b)) & 0xff));
}

// GLB (glTF 2.0 §4.4): header, JSON chunk padded with spaces, BIN chunk
// padded with zeros.
std::string glb(const json& document, std::string bin) {
    std::string text = document.dump();
    while (text.size() % 4 != 0) text += ' ';
    while (bin.size() % 4 != 0) bin += '\0';
    std::string out = "glTF";
    put32(out, 2);
    put32(out, static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    put32(out, static_cast<uint32_t>(text.size()));
    put32(out, 0x4E4F534Au);  // "JSON"
    out += text;
    put32(out, static_cast<uint32_t>(bin.size()));
    put32(out, 0x004E4942u);  // "BIN\0"
    out += bin;
    return out;
}

std::string glb_quad() {
    const std::string buffer = quad_buffer();
    return glb(gltf_quad_document("", buffer.size()), buffer);
}

// A 4x4-vertex grid with uvs, Draco-compressed (KHR_draco_mesh_compression).
std::string glb_draco_grid() {
    constexpr int n = 4;
    draco::Mesh dm;
    dm.set_num_points(n * n);
    std::vector<float> positions, uvs;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            positions.insert(positions.end(), {float(i), 0.1f * float((i * j) % 3), float(j)});
            uvs.insert(uvs.end(), {float(i) / (n - 1), float(j) / (n - 1)});
        }
    auto add = [&](draco::GeometryAttribute::Type type, int comps, const float* data) {
        draco::GeometryAttribute ga;
        ga.Init(type, nullptr, static_cast<uint8_t>(comps), draco::DT_FLOAT32, false,
                sizeof(float) * comps, 0);
        const int att = dm.AddAttribute(ga, /*identity_mapping=*/true, n * n);
        for (int i = 0; i < n * n; ++i)
            dm.attribute(att)->SetAttributeValue(draco::AttributeValueIndex(i), data + comps * i);
        return static_cast<int>(dm.attribute(att)->unique_id());
    };
    const int position_id = add(draco::GeometryAttribute::POSITION, 3, positions.data());
    const int uv_id = add(draco::GeometryAttribute::TEX_COORD, 2, uvs.data());
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const unsigned a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
            dm.AddFace({draco::PointIndex(a), draco::PointIndex(b), draco::PointIndex(c)});
            dm.AddFace({draco::PointIndex(a), draco::PointIndex(c), draco::PointIndex(d)});
        }
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 12);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 10);
    draco::EncoderBuffer buffer;
    if (!encoder.EncodeMeshToBuffer(dm, &buffer).ok()) fail("fuzz seeds: Draco encoding failed");
    const std::string bin = bytes_of(buffer.data(), buffer.size());
    const json doc = {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"KHR_draco_mesh_compression"}},
        {"extensionsRequired", {"KHR_draco_mesh_compression"}},
        {"buffers", json::array({{{"byteLength", bin.size()}}})},
        {"bufferViews", json::array({{{"buffer", 0}, {"byteLength", bin.size()}}})},
        {"accessors",
         json::array({
             {{"componentType", 5126},
              {"type", "VEC3"},
              {"count", n * n},
              {"min", {0, 0, 0}},
              {"max", {n - 1, 0.2, n - 1}}},
             {{"componentType", 5126}, {"type", "VEC2"}, {"count", n * n}},
             {{"componentType", 5125}, {"type", "SCALAR"}, {"count", 6 * (n - 1) * (n - 1)}},
         })},
        {"meshes",
         json::array(
             {{{"primitives",
                json::array({{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}},
                              {"indices", 2},
                              {"extensions",
                               {{"KHR_draco_mesh_compression",
                                 {{"bufferView", 0},
                                  {"attributes",
                                   {{"POSITION", position_id}, {"TEXCOORD_0", uv_id}}}}}}}}})}}})},
        {"nodes", json::array({{{"mesh", 0}}})},
        {"scenes", json::array({{{"nodes", {0}}}})},
    };
    return glb(doc, bin);
}

// A small lat-long map: a smooth gradient with a bright "sun" texel.
Image environment_image() {
    Image image(8, 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            image.at(x, y) = glm::vec3(0.2f + 0.1f * float(x), 0.5f, 1.0f - 0.2f * float(y));
    image.at(5, 1) = glm::vec3(500.0f, 400.0f, 300.0f);
    return image;
}

Image height_image() {
    Image image(5, 5);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            image.at(x, y) = glm::vec3(float((x * 3 + y * 7) % 5) / 4.0f);
    return image;
}

// A tangent-space normal map: tilts up to ~45° around the tile, one texel
// at the tangent plane (the clamped case), stored as PNG codes (n + 1)/2.
Image normal_image() {
    Image image(6, 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 n =
                glm::normalize(glm::vec3(float(x - 2) * 0.4f, float(y - 1) * 0.5f, 1.0f));
            image.at(x, y) =
                glm::vec3(srgb_decode(0.5f * (n.x + 1.0f)), srgb_decode(0.5f * (n.y + 1.0f)),
                          srgb_decode(0.5f * (n.z + 1.0f)));
        }
    image.at(5, 3) = glm::vec3(1.0f, srgb_decode(0.5f), srgb_decode(0.5f));  // (1, 0, 0)
    return image;
}

// A baseline JPEG of a 16 x 8 gradient (4:2:0, as stb writes below quality 90).
void write_jpeg_seed(const fs::path& path) {
    std::vector<unsigned char> rgb(3 * 16 * 8);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<unsigned char>((i * 37) % 251);
    if (!stbi_write_jpg(path.string().c_str(), 16, 8, 3, rgb.data(), 80))
        fail("{}: cannot write fuzzing seed", path.string());
}

void write_assets(const fs::path& dir) {
    write_file(dir / "mesh.obj", obj_quad());
    write_file(dir / "mesh.gltf", gltf_quad_json());
    write_file(dir / "mesh.glb", glb_quad());
    write_file(dir / "draco.glb", glb_draco_grid());
    write_exr(environment_image(), dir / "env.exr");
    write_hdr(environment_image(), dir / "env.hdr");
    write_png(height_image(), dir / "height.png");
    write_png(normal_image(), dir / "normal.png");
    write_jpeg_seed(dir / "photo.jpg");
}

fs::path g_scratch;

void remove_scratch() {
    std::error_code ec;
    if (!g_scratch.empty()) fs::remove_all(g_scratch, ec);
}

// Small scenes that reference each asset and exercise the optional blocks.
std::vector<std::pair<std::string, std::string>> asset_scenes() {
    const std::string head = R"({
  "film": {"width": 16, "height": 16, "exposure": 0.5,
           "bloom": {"strength": 0.1, "radius_px": 2, "threshold": 1, "apply_to_exr": false}},
  "camera": {"type": "perspective", "eye": [0, 2, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 40},
  "render": {"integrator": "path", "spp": 1, "max_depth": 4, "rr_depth": 3, "seed": 7},
  "materials": [
    {"name": "glint", "type": "glint", MODEL,
     "log_density": 10, "fresnel": {"type": "schlick", "f0": [0.9, 0.8, 0.7]}},
    {"name": "metal", "type": "conductor", "metal": "gold", "roughness": 0.1, "ndf": "ggx"},
    {"name": "glass", "type": "dielectric", "eta": 1.5, "roughness": 0.05}
  ],
)";
    // The glint material's model: deliot2023 under point and directional
    // lights, kneiphof2025 (which also shades sphere and environment lights)
    // otherwise.
    auto scene = [&](const std::string& shape, const std::string& light) {
        const bool near_lights = light.find("\"point\"") != std::string::npos ||
                                 light.find("\"directional\"") != std::string::npos;
        std::string text = head;
        text.replace(text.find("MODEL"), 5,
                     near_lights ? R"("model": "deliot2023", "roughness": [0.2, 0.3])"
                                 : R"("model": "kneiphof2025", "ndf": "ggx", "roughness": 0.3)");
        return text + "  \"shapes\": [" + shape + "],\n  \"lights\": [" + light + "],\n" +
               "  \"comment\": \"fuzz seed\"\n}\n";
    };
    const std::string point = R"({"type": "point", "position": [0, 3, 0], "intensity": [5, 5, 5]})";
    return {
        {"obj_box_uv.json", scene(R"({"type": "obj", "file": "mesh.obj", "material": "glint",
                   "uv": {"projection": "box", "scale": 2, "center": [0, 0, 0]},
                   "transform": {"scale": 0.5, "rotate": {"axis": [0, 1, 0], "deg": 30}, "translate": [0, 0.1, 0]}})",
                                  point)},
        {"gltf.json",
         scene(R"({"type": "gltf", "file": "mesh.gltf", "material": "metal"})",
               R"({"type": "environment", "file": "env.hdr", "scale": 0.5, "rotation_deg": 45})")},
        {"glb_planar.json",
         scene(
             R"({"type": "gltf", "file": "mesh.glb", "material": "glint",
                   "uv": {"projection": "planar", "axis": "y", "scale": 1}})",
             R"({"type": "directional", "direction": [0, -1, 0.2], "irradiance": [2, 2, 2], "solid_angle_sr": 0.01})")},
        {"draco_spherical.json",
         scene(
             R"({"type": "gltf", "file": "draco.glb", "material": "glint",
                   "uv": {"projection": "spherical", "axis": "z", "radius": 1}})",
             R"({"type": "sphere", "center": [0, 4, 0], "radius": 0.5, "radiance": [10, 10, 10]})")},
        {"heightfield_file.json",
         scene(R"({"type": "heightfield", "file": "height.png", "material": "glass", "size": [2, 2],
                   "resolution": 8, "amplitude": 0.1, "uv_scale": [2, 2]})",
               R"({"type": "environment", "file": "env.exr"})")},
        {"heightfield_noise_torus.json",
         scene(R"({"type": "heightfield", "material": "glint", "resolution": 6, "frequency": 3,
                   "octaves": 2, "seed": 5},
                  {"type": "torus", "material": "metal", "major_radius": 1, "minor_radius": 0.25,
                   "segments_major": 8, "segments_minor": 6,
                   "uv": {"projection": "cylindrical", "axis": "y"}},
                  {"type": "head", "material": "glint", "segments_phi": 8, "rings_theta": 4},
                  {"type": "quad", "material": "glass", "size": [1, 2], "uv_scale": [3, 3]},
                  {"type": "sphere", "material": "metal", "center": [0, 1, 0], "radius": 0.3})",
               R"({"type": "environment", "radiance": [0.5, 0.6, 0.7], "scale": 2})")},
        // Every key of the texture form (scene/texture_reader.h) on the
        // parameters that take one, reading the grey height.png and the
        // colour photo.jpg.
        {"textured.json", R"({
  "camera": {"eye": [0, 2, 4], "target": [0, 0, 0], "fov_deg": 40},
  "film": {"width": 16, "height": 16},
  "render": {"integrator": "path", "spp": 1, "max_depth": 3},
  "materials": [
    {"name": "glint", "type": "glint", "model": "deliot2023",
     "log_density": {"texture": "height.png", "scale": 4, "offset": 8, "wrap": "mirror",
                     "uv_transform": {"scale": [2, 3], "offset": [0.1, 0.2], "rotation_deg": 15}},
     "roughness": [{"texture": "height.png", "channel": "r", "scale": 0.5, "offset": 0.05}, 0.2],
     "color": {"texture": "photo.jpg", "colorspace": "srgb"},
     "fresnel": {"type": "conductor", "metal": "silver"}},
    {"name": "paint", "type": "plastic",
     "albedo": {"texture": "photo.jpg", "channel": "luminance", "colorspace": "linear", "wrap": "clamp"},
     "roughness": {"texture": "height.png", "channel": "a", "scale": 0.3, "wrap": "repeat"}}
  ],
  "shapes": [{"type": "quad", "material": "glint", "size": [2, 2], "uv_scale": [2, 2]},
             {"type": "sphere", "material": "paint", "center": [0, 0.5, 0], "radius": 0.4}],
  "lights": [{"type": "point", "position": [0, 3, 0], "intensity": [5, 5, 5]}],
  "comment": "fuzz seed"
}
)"},
        // Every key of the normal map (scene/normal_map_reader.h), on the
        // ground truth (per-facet composition) and on a smooth lobe.
        {"normal_mapped.json", R"({
  "camera": {"eye": [0, 2, 4], "target": [0, 0, 0], "fov_deg": 40},
  "film": {"width": 16, "height": 16},
  "render": {"integrator": "path", "spp": 1, "max_depth": 3},
  "materials": [
    {"name": "glint", "type": "glint", "model": "explicit", "log_density": 8, "curvature": "footprint",
     "normal_map": {"texture": "normal.png", "scale": 1.5, "encoding": "unorm", "filtering": "lean",
                    "wrap": "mirror", "uv_transform": {"scale": 3, "rotation_deg": 20}}},
    {"name": "metal", "type": "conductor", "roughness": 0.2,
     "normal_map": {"texture": "normal.png", "scale": -0.5, "filtering": "none", "wrap": "clamp"}},
    {"name": "plastic", "type": "plastic", "roughness": 0.3,
     "normal_map": {"texture": "normal.png", "filtering": "lean_mixture", "mixture": 3}}
  ],
  "shapes": [{"type": "quad", "material": "glint", "size": [2, 2], "uv_scale": [2, 2]},
             {"type": "sphere", "material": "metal", "center": [0, 0.5, 0], "radius": 0.4}],
  "lights": [{"type": "point", "position": [0, 3, 0], "intensity": [5, 5, 5]}],
  "comment": "fuzz seed"
}
)"},
        // glTF's metallic-roughness material written in the scene, with the
        // texture keys its file materials use (a colour scale, "power").
        {"metallic_roughness.json", R"({
  "camera": {"eye": [0, 2, 4], "target": [0, 0, 0], "fov_deg": 40},
  "film": {"width": 16, "height": 16},
  "render": {"integrator": "path", "spp": 1, "max_depth": 3},
  "materials": [
    {"name": "paint", "type": "metallic_roughness", "ndf": "ggx", "eta": 1.45,
     "base_color": {"texture": "photo.jpg", "scale": [0.9, 0.8, 0.7]},
     "metallic": {"texture": "height.png", "channel": "b"},
     "roughness": {"texture": "height.png", "channel": "g", "scale": 0.8, "power": 2}},
    {"name": "trim", "type": "metallic_roughness", "base_color": [0.9, 0.8, 0.6],
     "metallic": 0.5, "roughness": [0.2, 0.4]}
  ],
  "shapes": [{"type": "quad", "material": "paint", "size": [2, 2]},
             {"type": "sphere", "material": "trim", "center": [0, 0.5, 0], "radius": 0.4}],
  "lights": [{"type": "directional", "direction": [0, 1, 0.5], "irradiance": 2}],
  "comment": "fuzz seed"
}
)"},
    };
}

class ScopedMemoryLimit {
  public:
    ScopedMemoryLimit() { set_memory_limit(kMemoryLimit); }
    ~ScopedMemoryLimit() { set_memory_limit(std::nullopt); }
};

}  // namespace

std::string_view target_name(Target target) {
    switch (target) {
        case Target::Scene:
            return "scene";
        case Target::Gltf:
            return "gltf";
        case Target::Obj:
            return "obj";
        case Target::Image:
            return "image";
    }
    return "?";
}

std::optional<Target> target_from_name(std::string_view name) {
    for (Target t : kTargets)
        if (target_name(t) == name) return t;
    return std::nullopt;
}

const fs::path& scratch_dir() {
    static std::once_flag once;
    std::call_once(once, [] {
        std::error_code ec;
        // tmpfs where there is one: the image target writes a file per input.
        fs::path base = fs::is_directory("/dev/shm", ec) && access("/dev/shm", W_OK) == 0
                            ? fs::path("/dev/shm")
                            : fs::temp_directory_path();
        g_scratch = base / fmt::format("glintlab_fuzz_{}", getpid());
        fs::remove_all(g_scratch, ec);
        fs::create_directories(g_scratch);
        write_assets(g_scratch);
        std::atexit(remove_scratch);
    });
    return g_scratch;
}

Outcome run(Target target, const uint8_t* data, size_t size, std::string* error) {
    const fs::path& dir = scratch_dir();
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const ScopedMemoryLimit limit;
    try {
        switch (target) {
            case Target::Scene: {
                const fs::path file = dir / "input.json";
                std::istringstream in(bytes);
                const nlohmann::json document = parse_json(in, file.string());
                check_scene(parse_scene(document, file));
                break;
            }
            case Target::Gltf: {
                check_mesh(load_gltf_bytes(bytes, "input.gltf", dir), "glTF");
                // The file's materials too: their translation, and the
                // decoding of the images they read.
                const GltfScene scene = load_gltf_scene_bytes(bytes, "input.gltf", dir);
                for (const GltfScene::Part& part : scene.parts) check_mesh(part.mesh, "glTF part");
                break;
            }
            case Target::Obj:
                check_mesh(load_obj_text(bytes, "input.obj"), "OBJ");
                break;
            case Target::Image: {
                const char* ext = bytes.starts_with("v/1\x01") ? ".exr"
                                  : bytes.starts_with("#?")    ? ".hdr"
                                                               : ".png";
                const fs::path file = dir / (std::string("input") + ext);
                write_file(file, bytes);
                check_image(read_image(file), file.string());
                break;
            }
        }
    } catch (const Error& e) {
        if (error) *error = e.what();
        return Outcome::Rejected;
    }
    return Outcome::Accepted;
}

size_t write_seeds(Target target, const fs::path& dir, const fs::path& source_dir) {
    fs::create_directories(dir);
    const fs::path& assets = scratch_dir();
    size_t count = 0;
    auto put = [&](const std::string& name, const std::string& bytes) {
        write_file(dir / name, bytes);
        ++count;
    };
    auto copy_asset = [&](const std::string& name) { put(name, read_file(assets / name)); };
    switch (target) {
        case Target::Scene: {
            for (const auto& entry : fs::directory_iterator(source_dir / "scenes")) {
                if (entry.path().extension() != ".json") continue;
                std::ifstream in(entry.path());
                json doc = parse_json(in, entry.path().string());
                // Environment maps outside the repository become the scratch
                // directory's small env.exr (the fuzzer reads no big files).
                if (doc.contains("lights"))
                    for (json& light : doc["lights"])
                        if (light.contains("file")) light["file"] = "env.exr";
                // Generated meshes at most 16 cells a side: a 768² heightfield
                // takes a second to build under the sanitizers, and the fuzzer
                // would spend its time mutating that seed.
                // glTF assets of the repository's scenes are copied next
                // to the fuzzer's input under their file name.
                if (doc.contains("shapes"))
                    for (json& shape : doc["shapes"])
                        if (shape.contains("file") && shape["file"].is_string()) {
                            const fs::path file = shape["file"].get<std::string>();
                            const fs::path name = file.filename();
                            write_file(assets / name, read_file(source_dir / "scenes" / file));
                            shape["file"] = name.string();
                        }
                if (doc.contains("shapes"))
                    for (json& shape : doc["shapes"])
                        for (const char* key : {"resolution", "segments_major", "segments_minor",
                                                "segments_phi", "rings_theta"})
                            if (shape.contains(key) && shape[key].is_number_integer())
                                shape[key] = std::min(shape[key].get<int>(), 16);
                put(entry.path().filename().string(), doc.dump(2));
            }
            for (const auto& [name, text] : asset_scenes()) put(name, text);
            break;
        }
        case Target::Gltf:
            copy_asset("mesh.gltf");
            copy_asset("mesh.glb");
            copy_asset("draco.glb");
            // A file with materials, textures in its binary chunk and
            // KHR_texture_transform (scripts/make_gltf_asset.py).
            put("glint_tiles.glb", read_file(source_dir / "scenes" / "gltf" / "glint_tiles.glb"));
            break;
        case Target::Obj:
            put("quad.obj", obj_quad());
            put("polygons.obj", obj_polygons());
            break;
        case Target::Image:
            copy_asset("env.exr");
            copy_asset("env.hdr");
            copy_asset("height.png");
            copy_asset("normal.png");
            copy_asset("photo.jpg");
            break;
    }
    return count;
}

}  // namespace glintlab::fuzz
