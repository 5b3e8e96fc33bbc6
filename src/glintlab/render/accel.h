// Ray casting against the scene with Embree 3: triangle meshes, and spheres
// kept analytic (Embree sphere points) so their uv parameterization and its
// derivatives are exact.
#pragma once

#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "glintlab/scene/camera.h"
#include "glintlab/scene/scene.h"

namespace glintlab {

// Everything shading needs about a ray–surface hit, in world space.
struct SurfaceHit {
    float t = 0.0f;
    glm::vec3 p{0.0f};
    glm::vec3 ng{0.0f};  // unit geometric normal (outward for spheres, winding for meshes)
    glm::vec3 ns{0.0f};  // unit shading normal (interpolated vertex normals, or ng)
    glm::vec2 uv{0.0f};
    glm::vec3 dpdu{0.0f}, dpdv{0.0f};
    // ∂ns/∂u, ∂ns/∂v of the unit shading normal (pbrt-v4's dndu, dndv, made
    // orthogonal to ns): how the surface turns over a footprint, which the
    // ground truth composes with each facet and the filters widen by
    // (docs/MODELS.md, "Curved surfaces"). Zero on a flat triangle.
    glm::vec3 dndu{0.0f}, dndv{0.0f};
    // The interpolated vertex tangent (xyz, unnormalised) and glTF's
    // bitangent sign (w); w = 0: the mesh has none (mesh_tangents.h).
    glm::vec4 tangent{0.0f};
    bool has_uv = false;  // false: uv is the barycentric fallback of pbrt
    int shape = -1;
};

class Accelerator {
  public:
    explicit Accelerator(const Scene& scene);
    ~Accelerator();
    Accelerator(const Accelerator&) = delete;
    Accelerator& operator=(const Accelerator&) = delete;

    std::optional<SurfaceHit> intersect(const Ray& ray, float t_max) const;
    // True if anything blocks the segment origin + t·dir, t in (0, t_max).
    bool occluded(glm::vec3 origin, glm::vec3 dir, float t_max) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Origin for a ray leaving a surface at p towards dir, pushed off the surface
// along the geometric normal to avoid self-intersection.
glm::vec3 offset_ray_origin(const SurfaceHit& hit, glm::vec3 dir);

}  // namespace glintlab
