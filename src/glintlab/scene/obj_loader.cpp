#include "glintlab/scene/obj_loader.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <string_view>
#include <system_error>

#include <tiny_obj_loader.h>

#include "glintlab/core/error.h"
#include "glintlab/core/regular_file.h"

namespace glintlab {

namespace {

// Reads attribute `index` (a tinyobj index, -1 meaning absent) from a flat
// array of `Dim`-vectors, failing with the file name when out of range.
template <int Dim>
glm::vec<Dim, float> fetch(const std::vector<tinyobj::real_t>& values, int index, const char* what,
                           const std::filesystem::path& path) {
    const size_t count = values.size() / Dim;
    if (index < 0 || static_cast<size_t>(index) >= count)
        fail("{}: {} index {} out of range [1, {}]", path.string(), what, index + 1, count);
    glm::vec<Dim, float> v;
    for (int k = 0; k < Dim; ++k) v[k] = static_cast<float>(values[index * Dim + k]);
    return v;
}

// tinyobj reads "nan", "abc" and an empty field as 0 and "1,5" as 1 without
// a word, so the numbers of every v, vt and vn line are checked first: each
// field a complete finite decimal number, as many fields as the statement
// takes (v: 3, 4 with w or 6 with a colour; vt: 1 to 3; vn: 3).
void check_obj_numbers(std::string_view text, const std::string& name) {
    size_t line_number = 0;
    while (!text.empty()) {
        ++line_number;
        const size_t eol = text.find('\n');
        std::string_view line = text.substr(0, eol);
        text = eol == std::string_view::npos ? std::string_view() : text.substr(eol + 1);
        const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
        const auto next_field = [&]() {
            while (!line.empty() && is_space(line.front())) line.remove_prefix(1);
            size_t end = 0;
            while (end < line.size() && !is_space(line[end])) ++end;
            const std::string_view field = line.substr(0, end);
            line.remove_prefix(end);
            return field;
        };
        const std::string_view statement = next_field();
        size_t min_fields = 0, max_fields = 0;
        if (statement == "v")
            min_fields = 3, max_fields = 6;
        else if (statement == "vt")
            min_fields = 1, max_fields = 3;
        else if (statement == "vn")
            min_fields = 3, max_fields = 3;
        else
            continue;
        size_t count = 0;
        for (std::string_view field = next_field(); !field.empty(); field = next_field()) {
            if (field.front() == '#') break;
            ++count;
            std::string_view digits = field;
            if (digits.front() == '+') digits.remove_prefix(1);
            double x = 0.0;
            const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), x);
            if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(x))
                fail("{}:{}: {} field {} \"{}\" is not a finite decimal number", name, line_number,
                     statement, count, field.substr(0, 40));
        }
        if (count < min_fields || count > max_fields || (statement == "v" && count == 5))
            fail("{}:{}: {} has {} numbers (allowed: {})", name, line_number, statement, count,
                 statement == "v"    ? "3, 4 or 6"
                 : statement == "vt" ? "1 to 3"
                                     : "3");
    }
}

tinyobj::ObjReaderConfig reader_config() {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    return config;
}

// The mesh of a parsed file (`name` names it in messages).
TriangleMesh mesh_from_reader(const tinyobj::ObjReader& reader, const std::string& name) {
    const std::filesystem::path path(name);
    const tinyobj::attrib_t& attrib = reader.GetAttrib();

    // First pass: decide which attributes every face corner has.
    bool all_normals = true, all_uvs = true;
    size_t corners = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        for (const tinyobj::index_t& idx : shape.mesh.indices) {
            all_normals = all_normals && idx.normal_index >= 0;
            all_uvs = all_uvs && idx.texcoord_index >= 0;
            ++corners;
        }
    }
    if (corners == 0) fail("{}: OBJ file has no triangles", name);

    TriangleMesh mesh;
    // One output vertex per distinct (position, normal, uv) index triple;
    // dropped attributes take index -1 so they do not split vertices.
    std::map<std::array<int, 3>, unsigned> vertex_of;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& indices = shape.mesh.indices;
        size_t offset = 0;
        for (const unsigned char face_size : shape.mesh.num_face_vertices) {
            // With triangulate = true every face has 3 corners; anything else
            // means the polygon could not be split.
            if (face_size != 3)
                fail("{}: face with {} vertices could not be triangulated", name, face_size);
            glm::uvec3 tri;
            for (int k = 0; k < 3; ++k) {
                const tinyobj::index_t idx = indices[offset + k];
                const std::array<int, 3> key{idx.vertex_index, all_normals ? idx.normal_index : -1,
                                             all_uvs ? idx.texcoord_index : -1};
                auto [it, inserted] =
                    vertex_of.try_emplace(key, static_cast<unsigned>(mesh.positions.size()));
                if (inserted) {
                    mesh.positions.push_back(fetch<3>(attrib.vertices, key[0], "vertex", path));
                    if (all_normals) {
                        // OBJ does not require unit normals; shading does.
                        const glm::vec3 n = fetch<3>(attrib.normals, key[1], "normal", path);
                        const float len = glm::length(n);
                        mesh.normals.push_back(len > 0.0f ? n / len : n);
                    }
                    if (all_uvs)
                        mesh.uvs.push_back(fetch<2>(attrib.texcoords, key[2], "texcoord", path));
                }
                tri[k] = it->second;
            }
            mesh.triangles.push_back(tri);
            offset += face_size;
        }
    }
    mesh.validate(name);
    return mesh;
}

}  // namespace

TriangleMesh load_obj(const std::filesystem::path& path) {
    const std::string name = path.string();
    if (const std::string problem = regular_file_problem(path); !problem.empty())
        fail("{}: the OBJ file {}", name, problem);
    std::string text;
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) fail("{}: cannot open OBJ file", name);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    return load_obj_text(text, name);
}

TriangleMesh load_obj_text(const std::string& text, const std::string& name) {
    check_obj_numbers(text, name);
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, std::string(), reader_config()))
        fail("{}: cannot parse OBJ: {}", name, reader.Error());
    return mesh_from_reader(reader, name);
}

}  // namespace glintlab
