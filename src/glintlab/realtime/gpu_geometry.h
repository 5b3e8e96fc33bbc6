// CPU-side preparation of the shapes for the OpenGL renderer (no GL calls,
// unit-testable): interleaved world-space vertices, indices and the
// per-triangle frames the forward shader reads by gl_PrimitiveID.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "glintlab/scene/scene.h"

namespace glintlab {

struct GpuVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    glm::vec2 uv{0.0f};
    // Spheres: the analytic dp/du. Meshes with vertex tangents (normal-mapped
    // materials, scene/mesh_tangents.h): the tangent. Otherwise unused
    // (meshes use GpuTriangleFrame). w: glTF's bitangent sign, 0 for none.
    glm::vec4 dpdu{0.0f};
};
static_assert(sizeof(GpuVertex) == 12 * sizeof(float));

// std430 layout of the shader's TriangleFrame.
struct GpuTriangleFrame {
    glm::vec4 dpdu{0.0f};  // xyz: dp/du of the triangle's uv mapping (pbrt-v4 Triangle)
    glm::vec4 ng{0.0f};    // xyz: unit geometric normal cross(p1 - p0, p2 - p0)
};

struct GpuMeshData {
    std::vector<GpuVertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<GpuTriangleFrame> triangles;  // empty for spheres
    bool per_triangle_frame = false;
    bool has_normals = true;
    // A closed surface (a sphere; a mesh whose every edge joins exactly two
    // triangles, vertices welded by position): every direction below its
    // geometric tangent plane at a point is occluded by the surface itself,
    // as the CPU's shadow rays find. The forward pass, whose environment is
    // otherwise unshadowed, drops such directions.
    bool closed = false;
};

// Tessellation of analytic spheres: segments in phi (and half as many rings
// in theta) of scene/shapes.cpp make_sphere, whose uv = (phi / 2pi, theta /
// pi) is the parameterisation of the CPU's analytic sphere
// (render/accel.cpp). 192 segments (chord error 1.4e-4 r) while the scene's
// spheres stay within a budget of 300k triangles, fewer (down to 64: chord
// error 1.2e-3 r, 0.05 px for the 64 spheres of the MANY scene at 1080p)
// beyond it, so that many small spheres do not make the frame vertex-bound.
inline constexpr int kMaxSphereSegments = 192;
inline constexpr int kMinSphereSegments = 64;
inline constexpr double kSphereTriangleBudget = 300000.0;
int sphere_segments(const Scene& scene);

GpuMeshData gpu_mesh_data(const Shape& shape, int sphere_segments = kMaxSphereSegments);

// dp/du of triangle (p0, p1, p2) with uvs (uv0, uv1, uv2) exactly as
// render/accel.cpp triangle_hit, including its fallback for degenerate uvs.
glm::vec3 triangle_dpdu(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec2 uv0, glm::vec2 uv1,
                        glm::vec2 uv2);

// Bounding sphere (centre, radius) of every shape, for the depth range.
glm::vec4 scene_bounds(const Scene& scene);

}  // namespace glintlab
