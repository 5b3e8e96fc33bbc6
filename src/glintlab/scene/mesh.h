// Indexed triangle mesh: the one geometry type every shape and loader of
// glintlab produces and the renderers (Embree, OpenGL) consume.
#pragma once

#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace glintlab {

// The scene format's coordinate range, for mesh positions and uvs too: in
// single precision a coordinate of 1e10 leaves no room for ray offsets (it
// rendered black), and a uv of 1e16 has no fractional part for a texture or
// a glint grid to index.
inline constexpr float kMaxMeshCoordinate = 1e6f;

// Winding convention: a triangle (a, b, c) is counter-clockwise seen from the
// side its outward/front normal points to, i.e. the geometric normal
// cross(b - a, c - a) agrees with the shading normals.
struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // per vertex, may be empty (then faceted shading)
    std::vector<glm::vec2> uvs;      // per vertex, may be empty (no uv parameterization)
    // Per vertex (xyz unit tangent along ∂p/∂u, w = ±1: glTF's bitangent
    // sign), may be empty; generated for the meshes of normal-mapped
    // materials (mesh_tangents.h).
    std::vector<glm::vec4> tangents;
    std::vector<glm::uvec3> triangles;

    bool has_uvs() const { return !uvs.empty(); }
    bool has_normals() const { return !normals.empty(); }

    // Throws glintlab::Error naming `what` (typically the file or the scene
    // key the mesh came from) unless: there is at least one triangle, every
    // index is in range, normals/uvs are empty or one per position, every
    // value is finite, and positions and uvs lie in ±kMaxMeshCoordinate.
    void validate(std::string_view what) const;
};

// Appends `src` to `dst`, offsetting its indices. A per-vertex attribute that
// only one of the two meshes has cannot be kept for the merged vertices, so
// it is dropped (normals: faceted shading; uvs: no parameterization).
void append_mesh(TriangleMesh& dst, const TriangleMesh& src);

// Sum of the triangle areas.
double surface_area(const TriangleMesh& mesh);

// Geometric (unnormalised, length = 2 * area) normal of triangle `t`.
glm::vec3 geometric_normal(const TriangleMesh& mesh, size_t t);

}  // namespace glintlab
