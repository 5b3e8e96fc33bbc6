#include "glintlab/scene/uv_projection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>

#include <glm/gtc/constants.hpp>

#include "glintlab/core/error.h"

namespace glintlab {

void uv_projection_frame(int axis, int sign, glm::vec3* t, glm::vec3* b, glm::vec3* n) {
    static const glm::vec3 kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);
    switch (axis) {
        case 0:
            *t = sign > 0 ? -kZ : kZ, *b = kY, *n = sign > 0 ? kX : -kX;
            break;
        case 1:
            *t = kX, *b = sign > 0 ? -kZ : kZ, *n = sign > 0 ? kY : -kY;
            break;
        case 2:
            *t = sign > 0 ? kX : -kX, *b = kY, *n = sign > 0 ? kZ : -kZ;
            break;
        default:
            fail("uv projection: axis {} is not 0, 1 or 2", axis);
    }
}

void project_uvs(TriangleMesh& mesh, const UvProjection& proj) {
    using Type = UvProjection::Type;
    glm::vec3 t, b, n;
    uv_projection_frame(proj.axis, 1, &t, &b, &n);
    const float s = proj.scale;

    float rho = proj.radius;
    if ((proj.type == Type::Cylindrical || proj.type == Type::Spherical) && !(rho > 0.0f)) {
        rho = 0.0f;
        for (glm::vec3 p : mesh.positions) {
            const glm::vec3 d = p - proj.center;
            rho = std::max(rho, proj.type == Type::Spherical ? glm::length(d)
                                                             : glm::length(d - glm::dot(d, n) * n));
        }
        if (!(rho > 0.0f)) rho = 1.0f;  // every vertex on the axis/center: any ρ will do
    }
    // Corners closer to the axis than this have no meaningful φ.
    const float axis_eps = 1e-6f * rho;

    std::vector<glm::vec2> corner_uv(3 * mesh.triangles.size());
    for (size_t tri = 0; tri < mesh.triangles.size(); ++tri) {
        const glm::uvec3 idx = mesh.triangles[tri];
        glm::vec3 d[3];
        for (int k = 0; k < 3; ++k) d[k] = mesh.positions[idx[k]] - proj.center;
        glm::vec2* uv = &corner_uv[3 * tri];
        if (proj.type == Type::Planar || proj.type == Type::Box) {
            glm::vec3 ft = t, fb = b, fn = n;
            if (proj.type == Type::Box) {
                // Dominant axis of the geometric normal; ties go to the lower
                // axis so the choice is deterministic.
                const glm::vec3 g = glm::cross(d[1] - d[0], d[2] - d[0]);
                const glm::vec3 a = glm::abs(g);
                const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
                uv_projection_frame(axis, g[axis] >= 0.0f ? 1 : -1, &ft, &fb, &fn);
            }
            for (int k = 0; k < 3; ++k)
                uv[k] = s * glm::vec2(glm::dot(d[k], ft), glm::dot(d[k], fb));
            continue;
        }
        float phi[3], v[3];
        bool on_axis[3];
        for (int k = 0; k < 3; ++k) {
            const float x = glm::dot(d[k], t), y = glm::dot(d[k], b), h = glm::dot(d[k], n);
            on_axis[k] = std::sqrt(x * x + y * y) <= axis_eps;
            phi[k] = on_axis[k] ? 0.0f : std::atan2(y, x);
            if (proj.type == Type::Cylindrical) {
                v[k] = s * h;
            } else {
                const float r = glm::length(d[k]);
                v[k] = r > 0.0f ? s * rho * std::clamp(h / r, -1.0f, 1.0f) : 0.0f;
            }
        }
        // Unwrap φ around the first corner that has one.
        int ref = -1;
        for (int k = 0; k < 3 && ref < 0; ++k)
            if (!on_axis[k]) ref = k;
        float sum = 0.0f;
        int with_phi = 0;
        for (int k = 0; k < 3; ++k) {
            if (on_axis[k]) continue;
            phi[k] += glm::two_pi<float>() *
                      std::round((phi[ref] - phi[k]) * glm::one_over_two_pi<float>());
            sum += phi[k];
            ++with_phi;
        }
        for (int k = 0; k < 3; ++k)
            if (on_axis[k]) phi[k] = with_phi > 0 ? sum / static_cast<float>(with_phi) : 0.0f;
        for (int k = 0; k < 3; ++k) uv[k] = {s * rho * phi[k], v[k]};
    }

    // Weld corners that share a vertex and a uv (bitwise), so a vertex is
    // split only where its uv really differs between triangles.
    TriangleMesh out;
    out.triangles.resize(mesh.triangles.size());
    std::map<std::array<uint32_t, 3>, uint32_t> vertex_of;
    for (size_t tri = 0; tri < mesh.triangles.size(); ++tri)
        for (int k = 0; k < 3; ++k) {
            const uint32_t src = mesh.triangles[tri][k];
            const glm::vec2 uv = corner_uv[3 * tri + k];
            std::array<uint32_t, 3> key{src, 0, 0};
            std::memcpy(&key[1], &uv.x, 4);
            std::memcpy(&key[2], &uv.y, 4);
            auto [it, inserted] =
                vertex_of.try_emplace(key, static_cast<uint32_t>(out.positions.size()));
            if (inserted) {
                out.positions.push_back(mesh.positions[src]);
                if (mesh.has_normals()) out.normals.push_back(mesh.normals[src]);
                out.uvs.push_back(uv);
            }
            out.triangles[tri][k] = it->second;
        }
    mesh = std::move(out);
}

}  // namespace glintlab
