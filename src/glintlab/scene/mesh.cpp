#include "glintlab/scene/mesh.h"

#include <cmath>

#include <fmt/format.h>

#include "glintlab/core/error.h"

namespace glintlab {

namespace {

bool all_finite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool all_finite(glm::vec2 v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}
template <int N>
bool within(glm::vec<N, float> v, float bound) {
    for (int k = 0; k < N; ++k)
        if (!(std::abs(v[k]) <= bound)) return false;
    return true;
}

}  // namespace

void TriangleMesh::validate(std::string_view what) const {
    if (triangles.empty() || positions.empty()) fail("{}: mesh has no triangles", what);
    if (!normals.empty() && normals.size() != positions.size())
        fail("{}: mesh has {} normals for {} positions (must be 0 or equal)", what, normals.size(),
             positions.size());
    if (!uvs.empty() && uvs.size() != positions.size())
        fail("{}: mesh has {} uvs for {} positions (must be 0 or equal)", what, uvs.size(),
             positions.size());
    if (!tangents.empty() && tangents.size() != positions.size())
        fail("{}: mesh has {} tangents for {} positions (must be 0 or equal)", what,
             tangents.size(), positions.size());
    const size_t n = positions.size();
    for (size_t t = 0; t < triangles.size(); ++t) {
        const glm::uvec3 tri = triangles[t];
        for (int k = 0; k < 3; ++k)
            if (tri[k] >= n)
                fail("{}: triangle {} has vertex index {} out of range [0, {})", what, t, tri[k],
                     n);
    }
    for (size_t i = 0; i < n; ++i) {
        if (!all_finite(positions[i])) fail("{}: position {} is not finite", what, i);
        if (!within(positions[i], kMaxMeshCoordinate))
            fail(
                "{}: position {} = ({:g}, {:g}, {:g}) out of range: coordinates must lie in "
                "[-1e6, 1e6]",
                what, i, positions[i].x, positions[i].y, positions[i].z);
    }
    for (size_t i = 0; i < normals.size(); ++i)
        if (!all_finite(normals[i])) fail("{}: normal {} is not finite", what, i);
    for (size_t i = 0; i < uvs.size(); ++i) {
        if (!all_finite(uvs[i])) fail("{}: uv {} is not finite", what, i);
        if (!within(uvs[i], kMaxMeshCoordinate))
            fail("{}: uv {} = ({:g}, {:g}) out of range: uvs must lie in [-1e6, 1e6]", what, i,
                 uvs[i].x, uvs[i].y);
    }
    for (size_t i = 0; i < tangents.size(); ++i) {
        if (!all_finite(glm::vec3(tangents[i])) || !std::isfinite(tangents[i].w))
            fail("{}: tangent {} is not finite", what, i);
        if (tangents[i].w != 1.0f && tangents[i].w != -1.0f)
            fail("{}: tangent {} has w = {:g}: the bitangent sign must be 1 or -1", what, i,
                 tangents[i].w);
    }
}

void append_mesh(TriangleMesh& dst, const TriangleMesh& src) {
    if (src.triangles.empty()) return;
    if (dst.triangles.empty() && dst.positions.empty()) {
        dst = src;
        return;
    }
    const bool keep_normals = dst.has_normals() && src.has_normals();
    const bool keep_uvs = dst.has_uvs() && src.has_uvs();
    const auto offset = static_cast<unsigned>(dst.positions.size());
    dst.positions.insert(dst.positions.end(), src.positions.begin(), src.positions.end());
    if (keep_normals)
        dst.normals.insert(dst.normals.end(), src.normals.begin(), src.normals.end());
    else
        dst.normals.clear();
    if (keep_uvs)
        dst.uvs.insert(dst.uvs.end(), src.uvs.begin(), src.uvs.end());
    else
        dst.uvs.clear();
    if (!dst.tangents.empty() && !src.tangents.empty())
        dst.tangents.insert(dst.tangents.end(), src.tangents.begin(), src.tangents.end());
    else
        dst.tangents.clear();
    dst.triangles.reserve(dst.triangles.size() + src.triangles.size());
    for (const glm::uvec3& t : src.triangles) dst.triangles.push_back(t + glm::uvec3(offset));
}

glm::vec3 geometric_normal(const TriangleMesh& mesh, size_t t) {
    const glm::uvec3 tri = mesh.triangles[t];
    const glm::vec3 a = mesh.positions[tri.x];
    return glm::cross(mesh.positions[tri.y] - a, mesh.positions[tri.z] - a);
}

double surface_area(const TriangleMesh& mesh) {
    double area = 0.0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        // Accumulate in double: the sum over many tiny triangles is what the
        // convergence tests compare to the analytic area.
        const glm::uvec3 tri = mesh.triangles[t];
        const glm::dvec3 a(mesh.positions[tri.x]);
        area += 0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[tri.y]) - a,
                                             glm::dvec3(mesh.positions[tri.z]) - a));
    }
    return area;
}

}  // namespace glintlab
