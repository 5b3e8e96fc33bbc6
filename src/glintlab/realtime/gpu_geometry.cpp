#include "glintlab/realtime/gpu_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <tuple>
#include <unordered_map>

#include <glm/gtc/constants.hpp>

#include "glintlab/scene/shapes.h"

namespace glintlab {

glm::vec3 triangle_dpdu(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec2 uv0, glm::vec2 uv1,
                        glm::vec2 uv2) {
    const glm::vec3 ng = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    const glm::vec2 duv02 = uv0 - uv2, duv12 = uv1 - uv2;
    const glm::vec3 dp02 = p0 - p2, dp12 = p1 - p2;
    const float det = duv02.x * duv12.y - duv02.y * duv12.x;
    if (std::abs(det) >= 1e-12f) {
        const float inv = 1.0f / det;
        const glm::vec3 dpdu = (duv12.y * dp02 - duv02.y * dp12) * inv;
        const glm::vec3 dpdv = (duv02.x * dp12 - duv12.x * dp02) * inv;
        const bool finite = std::isfinite(dpdu.x + dpdu.y + dpdu.z + dpdv.x + dpdv.y + dpdv.z);
        if (finite && glm::length(glm::cross(dpdu, dpdv)) != 0.0f) return dpdu;
    }
    const glm::vec3 a = std::abs(ng.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    return glm::normalize(glm::cross(ng, a));
}

int sphere_segments(const Scene& scene) {
    const auto spheres = std::count_if(
        scene.shapes.begin(), scene.shapes.end(),
        [](const Shape& s) { return std::holds_alternative<SphereGeometry>(s.geometry); });
    if (spheres == 0) return kMaxSphereSegments;
    // segments^2 triangles per sphere (segments x segments / 2 quads).
    const int n = static_cast<int>(std::sqrt(kSphereTriangleBudget / static_cast<double>(spheres)));
    return std::clamp(n - n % 2, kMinSphereSegments, kMaxSphereSegments);
}

namespace {

// Every undirected edge, over vertices welded by exact position (meshes
// repeat a vertex along uv seams), used by exactly two triangles.
bool mesh_is_closed(const TriangleMesh& m) {
    if (m.triangles.empty()) return false;
    std::map<std::tuple<float, float, float>, uint32_t> welded;
    std::vector<uint32_t> id(m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const glm::vec3 p = m.positions[i];
        id[i] = welded.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<uint32_t>(welded.size()))
                    .first->second;
    }
    std::unordered_map<uint64_t, int> uses;
    for (const glm::uvec3& t : m.triangles) {
        const uint32_t v[3] = {id[t.x], id[t.y], id[t.z]};
        for (int e = 0; e < 3; ++e) {
            const uint64_t a = std::min(v[e], v[(e + 1) % 3]), b = std::max(v[e], v[(e + 1) % 3]);
            if (a == b) return false;  // a degenerate triangle
            ++uses[(a << 32) | b];
        }
    }
    for (const auto& [edge, n] : uses)
        if (n != 2) return false;
    return true;
}

}  // namespace

GpuMeshData gpu_mesh_data(const Shape& shape, int segments) {
    GpuMeshData out;
    if (const auto* s = std::get_if<SphereGeometry>(&shape.geometry)) {
        const TriangleMesh m = make_sphere(s->radius, segments, segments / 2);
        out.vertices.resize(m.positions.size());
        for (size_t i = 0; i < m.positions.size(); ++i) {
            GpuVertex& v = out.vertices[i];
            const glm::vec3 n = m.normals[i];
            v.position = s->center + s->rotation * m.positions[i];
            v.normal = s->rotation * n;
            v.uv = m.uvs[i];
            // render/accel.cpp sphere_hit: dp/du = 2 pi dp/dphi in the object
            // frame, rotated to world (zero at the poles: the shader then
            // falls back to an orthonormal basis).
            const float theta = v.uv.y * glm::pi<float>(), phi = v.uv.x * glm::two_pi<float>();
            const float st = std::sin(theta);
            const glm::vec3 dpdphi =
                s->radius * glm::vec3(-st * std::sin(phi), 0.0f, st * std::cos(phi));
            const glm::vec3 dpdu = s->rotation * (glm::two_pi<float>() * dpdphi);
            // The normal map's bitangent sign (render/surface_bsdf.cpp
            // local_bump): +1 where n × dp/du points against dp/dv.
            const glm::vec3 dpdtheta = s->radius * glm::vec3(std::cos(theta) * std::cos(phi), -st,
                                                             std::cos(theta) * std::sin(phi));
            const float side = glm::dot(glm::cross(v.normal, dpdu), s->rotation * dpdtheta);
            v.dpdu = glm::vec4(dpdu, side <= 0.0f ? 1.0f : -1.0f);
        }
        out.indices.reserve(m.triangles.size() * 3);
        for (const glm::uvec3& t : m.triangles)
            out.indices.insert(out.indices.end(), {t.x, t.y, t.z});
        out.per_triangle_frame = false;
        out.has_normals = true;
        out.closed = true;
        return out;
    }
    const TriangleMesh& m = std::get<TriangleMesh>(shape.geometry);
    out.vertices.resize(m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
        out.vertices[i].position = m.positions[i];
        if (m.has_normals()) out.vertices[i].normal = m.normals[i];
        if (m.has_uvs()) out.vertices[i].uv = m.uvs[i];
        if (!m.tangents.empty()) out.vertices[i].dpdu = m.tangents[i];
    }
    out.indices.reserve(m.triangles.size() * 3);
    out.triangles.resize(m.triangles.size());
    for (size_t k = 0; k < m.triangles.size(); ++k) {
        const glm::uvec3 t = m.triangles[k];
        out.indices.insert(out.indices.end(), {t.x, t.y, t.z});
        const glm::vec3 p0 = m.positions[t.x], p1 = m.positions[t.y], p2 = m.positions[t.z];
        // Meshes without uvs: the CPU's per-triangle default (0,0), (1,0), (1,1).
        glm::vec2 uv0(0.0f, 0.0f), uv1(1.0f, 0.0f), uv2(1.0f, 1.0f);
        if (m.has_uvs()) uv0 = m.uvs[t.x], uv1 = m.uvs[t.y], uv2 = m.uvs[t.z];
        out.triangles[k].dpdu = glm::vec4(triangle_dpdu(p0, p1, p2, uv0, uv1, uv2), 0.0f);
        out.triangles[k].ng = glm::vec4(glm::normalize(glm::cross(p1 - p0, p2 - p0)), 0.0f);
    }
    out.per_triangle_frame = true;
    out.has_normals = m.has_normals();
    out.closed = mesh_is_closed(m);
    return out;
}

glm::vec4 scene_bounds(const Scene& scene) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const Shape& shape : scene.shapes) {
        if (const auto* s = std::get_if<SphereGeometry>(&shape.geometry)) {
            lo = glm::min(lo, s->center - s->radius);
            hi = glm::max(hi, s->center + s->radius);
        } else {
            for (const glm::vec3& p : std::get<TriangleMesh>(shape.geometry).positions) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
        }
    }
    if (lo.x > hi.x) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    const glm::vec3 c = 0.5f * (lo + hi);
    return glm::vec4(c, std::max(0.5f * glm::length(hi - lo), 1e-6f));
}

}  // namespace glintlab
