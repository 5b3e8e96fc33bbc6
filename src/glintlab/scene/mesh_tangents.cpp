#include "glintlab/scene/mesh_tangents.h"

#include <algorithm>
#include <cmath>

namespace glintlab {
namespace {

float angle_at(glm::vec3 a, glm::vec3 b, glm::vec3 c) {  // the angle at a
    const glm::vec3 u = b - a, v = c - a;
    const float lu = glm::length(u), lv = glm::length(v);
    if (!(lu > 0.0f && lv > 0.0f)) return 0.0f;
    return std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0f, 1.0f));
}

}  // namespace

size_t generate_vertex_tangents(TriangleMesh& mesh) {
    const size_t n = mesh.positions.size();
    std::vector<glm::vec3> sum_dpdu(n, glm::vec3(0.0f)), sum_dpdv(n, glm::vec3(0.0f));
    std::vector<glm::vec3> sum_normal(n, glm::vec3(0.0f));
    for (const glm::uvec3& tri : mesh.triangles) {
        const glm::vec3 p[3] = {mesh.positions[tri.x], mesh.positions[tri.y],
                                mesh.positions[tri.z]};
        const glm::vec2 uv[3] = {mesh.uvs[tri.x], mesh.uvs[tri.y], mesh.uvs[tri.z]};
        // ∂p/∂u, ∂p/∂v of the triangle's uv mapping (as the renderers' hits).
        const glm::vec2 duv02 = uv[0] - uv[2], duv12 = uv[1] - uv[2];
        const glm::vec3 dp02 = p[0] - p[2], dp12 = p[1] - p[2];
        const float det = duv02.x * duv12.y - duv02.y * duv12.x;
        glm::vec3 dpdu(0.0f), dpdv(0.0f);
        if (std::abs(det) >= 1e-12f) {
            dpdu = (duv12.y * dp02 - duv02.y * dp12) / det;
            dpdv = (duv02.x * dp12 - duv12.x * dp02) / det;
            // MikkTSpace weighs directions, not magnitudes.
            const float lu = glm::length(dpdu), lv = glm::length(dpdv);
            dpdu = lu > 0.0f && std::isfinite(lu) ? dpdu / lu : glm::vec3(0.0f);
            dpdv = lv > 0.0f && std::isfinite(lv) ? dpdv / lv : glm::vec3(0.0f);
        }
        const glm::vec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
        const float face_length = glm::length(face);
        const glm::vec3 face_normal = face_length > 0.0f ? face / face_length : glm::vec3(0.0f);
        for (int k = 0; k < 3; ++k) {
            const float w = angle_at(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
            const unsigned v = tri[k];
            sum_dpdu[v] += w * dpdu;
            sum_dpdv[v] += w * dpdv;
            sum_normal[v] += w * face_normal;
        }
    }
    mesh.tangents.assign(n, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    size_t fixed = 0;
    for (size_t v = 0; v < n; ++v) {
        glm::vec3 normal = mesh.has_normals() ? mesh.normals[v] : sum_normal[v];
        const float ln = glm::length(normal);
        normal = ln > 0.0f ? normal / ln : glm::vec3(0.0f, 0.0f, 1.0f);
        glm::vec3 t = sum_dpdu[v] - normal * glm::dot(normal, sum_dpdu[v]);
        const float lt = glm::length(t);
        if (lt > 1e-6f && std::isfinite(lt)) {
            t /= lt;
        } else {
            const glm::vec3 a = std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
            t = glm::normalize(glm::cross(normal, a));
            ++fixed;
        }
        // glTF's bitangent n × t · w is "up" in the image: against ∂p/∂v.
        const float w = glm::dot(glm::cross(normal, t), sum_dpdv[v]) <= 0.0f ? 1.0f : -1.0f;
        mesh.tangents[v] = glm::vec4(t, w);
    }
    return fixed;
}

}  // namespace glintlab
