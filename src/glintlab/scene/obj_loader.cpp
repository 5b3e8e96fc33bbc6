#include "glintlab/scene/obj_loader.h"

#include <array>
#include <map>
#include <system_error>

#include <tiny_obj_loader.h>

#include "glintlab/core/error.h"

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
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail("{}: OBJ file not found", name);
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(name, reader_config()))
        fail("{}: cannot parse OBJ: {}", name, reader.Error());
    return mesh_from_reader(reader, name);
}

TriangleMesh load_obj_text(const std::string& text, const std::string& name) {
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, std::string(), reader_config()))
        fail("{}: cannot parse OBJ: {}", name, reader.Error());
    return mesh_from_reader(reader, name);
}

}  // namespace glintlab
