#include "glintlab/scene/shapes.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "glintlab/core/error.h"

namespace glintlab {

namespace {

void require_positive(const char* shape, const char* key, float value) {
    if (!(value > 0.0f) || !std::isfinite(value))
        fail("{}: {} must be a finite number > 0, got {}", shape, key, value);
}

void require_at_least(const char* shape, const char* key, int value, int minimum) {
    // The upper bound keeps the vertex count within 32-bit indices.
    constexpr int kMaximum = 1 << 14;
    if (value < minimum || value > kMaximum)
        fail("{}: {} must be in [{}, {}], got {}", shape, key, minimum, kMaximum, value);
}

struct GridVertex {
    glm::vec3 position, normal;
};

// The (columns + 1) × (rows + 1) vertices of a parametric surface sampled at
// u = i / columns, v = j / rows (rows outer), uv = (u, v) · uv_scale; the
// caller adds the triangles (add_grid_triangles).
template <class Surface>
TriangleMesh make_uv_grid(int columns, int rows, glm::vec2 uv_scale, Surface surface) {
    TriangleMesh mesh;
    const size_t count = static_cast<size_t>(columns + 1) * (rows + 1);
    mesh.positions.reserve(count);
    mesh.normals.reserve(count);
    mesh.uvs.reserve(count);
    for (int j = 0; j <= rows; ++j) {
        const float v = static_cast<float>(j) / static_cast<float>(rows);
        for (int i = 0; i <= columns; ++i) {
            const float u = static_cast<float>(i) / static_cast<float>(columns);
            const GridVertex g = surface(u, v);
            mesh.positions.push_back(g.position);
            mesh.normals.push_back(g.normal);
            mesh.uvs.push_back(glm::vec2(u, v) * uv_scale);
        }
    }
    return mesh;
}

// Emits the two triangles of every cell of a (columns+1) x (rows+1) vertex
// grid laid out row-major, counter-clockwise when column index increases
// along the first tangent and row index along the second.
// With `pole_rows`, the first and last rows collapse to a point (sphere
// poles), so the degenerate half of each of their cells is dropped.
void add_grid_triangles(TriangleMesh& mesh, int columns, int rows, bool pole_rows) {
    const auto stride = static_cast<unsigned>(columns + 1);
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
            const unsigned a = static_cast<unsigned>(j) * stride + static_cast<unsigned>(i);
            const unsigned b = a + 1;
            const unsigned c = b + stride;
            const unsigned d = a + stride;
            // In the first row a and b coincide (pole); in the last, c and d.
            if (!(pole_rows && j == 0)) mesh.triangles.emplace_back(a, b, c);
            if (!(pole_rows && j == rows - 1)) mesh.triangles.emplace_back(a, c, d);
        }
    }
}

}  // namespace

TriangleMesh make_quad(glm::vec2 size, glm::vec2 uv_scale) {
    require_positive("quad", "size.x", size.x);
    require_positive("quad", "size.y", size.y);
    const glm::vec2 h = 0.5f * size;
    TriangleMesh mesh;
    mesh.positions = {{-h.x, 0, h.y}, {h.x, 0, h.y}, {h.x, 0, -h.y}, {-h.x, 0, -h.y}};
    mesh.normals.assign(4, glm::vec3(0, 1, 0));
    mesh.uvs = {{0, 0}, {uv_scale.x, 0}, {uv_scale.x, uv_scale.y}, {0, uv_scale.y}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    return mesh;
}

TriangleMesh make_sphere(float radius, int segments_phi, int rings_theta) {
    require_positive("sphere", "radius", radius);
    require_at_least("sphere", "segments_phi", segments_phi, 3);
    require_at_least("sphere", "rings_theta", rings_theta, 2);
    TriangleMesh mesh =
        make_uv_grid(segments_phi, rings_theta, glm::vec2(1.0f), [&](float u, float v) {
            const float theta = v * glm::pi<float>();
            const float phi = u * glm::two_pi<float>();
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            return GridVertex{radius * n, n};
        });
    // cross(dp/dphi, dp/dtheta) points outward, so phi is the first grid
    // direction and theta the second.
    add_grid_triangles(mesh, segments_phi, rings_theta, /*pole_rows=*/true);
    return mesh;
}

TriangleMesh make_torus(float major_radius, float minor_radius, int segments_major,
                        int segments_minor, glm::vec2 uv_scale) {
    require_positive("torus", "major_radius", major_radius);
    require_positive("torus", "minor_radius", minor_radius);
    require_at_least("torus", "segments_major", segments_major, 3);
    require_at_least("torus", "segments_minor", segments_minor, 3);
    TriangleMesh mesh =
        make_uv_grid(segments_major, segments_minor, uv_scale, [&](float u, float v) {
            const float b = v * glm::two_pi<float>();
            const float a = u * glm::two_pi<float>();
            const glm::vec3 n(std::cos(b) * std::cos(a), std::sin(b), -std::cos(b) * std::sin(a));
            const glm::vec3 centre(major_radius * std::cos(a), 0.0f, -major_radius * std::sin(a));
            return GridVertex{centre + minor_radius * n, n};
        });
    // cross(dp/da, dp/db) points away from the tube axis.
    add_grid_triangles(mesh, segments_major, segments_minor, /*pole_rows=*/false);
    return mesh;
}

namespace {

// Radius of the head along the unit direction d: a unit sphere plus bumps
// exp((d·c − 1) / w) centred on feature directions c (w: angular width²/2).
float head_radius(glm::vec3 d) {
    auto bump = [&](glm::vec3 c, float height, float width) {
        return height * std::exp((glm::dot(d, glm::normalize(c)) - 1.0f) / width);
    };
    float r = 1.0f;
    r += bump({0.0f, -0.35f, 1.0f}, 0.28f, 0.06f);   // muzzle
    r += bump({0.0f, 0.32f, 1.0f}, 0.10f, 0.04f);    // brow ridge
    r += bump({0.0f, -0.2f, -1.0f}, 0.06f, 0.3f);    // back of the skull
    r -= bump({0.36f, 0.15f, 1.0f}, 0.10f, 0.008f);  // eye sockets
    r -= bump({-0.36f, 0.15f, 1.0f}, 0.10f, 0.008f);
    r += bump({1.0f, 0.12f, -0.08f}, 0.55f, 0.010f);  // ears
    r += bump({-1.0f, 0.12f, -0.08f}, 0.55f, 0.010f);
    return r;
}

glm::vec3 head_point(float theta, float phi) {
    // phi = 0 looks along -z, so the uv seam sits at the back of the head.
    const float a = phi - glm::half_pi<float>();
    const glm::vec3 d(std::sin(theta) * std::cos(a), std::cos(theta),
                      std::sin(theta) * std::sin(a));
    return head_radius(d) * d * glm::vec3(0.95f, 1.05f, 0.92f);
}

}  // namespace

TriangleMesh make_head(int segments_phi, int rings_theta, glm::vec2 uv_scale) {
    require_at_least("head", "segments_phi", segments_phi, 3);
    require_at_least("head", "rings_theta", rings_theta, 2);
    TriangleMesh mesh;
    const size_t count = static_cast<size_t>(segments_phi + 1) * (rings_theta + 1);
    mesh.positions.reserve(count);
    mesh.normals.reserve(count);
    mesh.uvs.reserve(count);
    constexpr float kStep = 1e-3f;  // central differences for the tangents
    for (int j = 0; j <= rings_theta; ++j) {
        const float v = static_cast<float>(j) / static_cast<float>(rings_theta);
        const float theta = v * glm::pi<float>();
        // Tangents at the poles from a ring just off the pole (dp/dphi = 0 there).
        const float tc = std::clamp(theta, 2.0f * kStep, glm::pi<float>() - 2.0f * kStep);
        for (int i = 0; i <= segments_phi; ++i) {
            const float u = static_cast<float>(i) / static_cast<float>(segments_phi);
            const float phi = u * glm::two_pi<float>();
            const glm::vec3 dphi = head_point(tc, phi + kStep) - head_point(tc, phi - kStep);
            const glm::vec3 dtheta = head_point(tc + kStep, phi) - head_point(tc - kStep, phi);
            // Same orientation as make_sphere: cross(dp/dphi, dp/dtheta) points outward.
            mesh.positions.push_back(head_point(theta, phi));
            mesh.normals.push_back(glm::normalize(glm::cross(dphi, dtheta)));
            mesh.uvs.push_back(glm::vec2(u, v) * uv_scale);
        }
    }
    add_grid_triangles(mesh, segments_phi, rings_theta, /*pole_rows=*/true);
    return mesh;
}

}  // namespace glintlab
