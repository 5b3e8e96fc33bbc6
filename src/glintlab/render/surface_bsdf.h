// The BSDF at a surface hit: the material's lobe (microfacet/bxdfs.h or a
// glint model) in the local shading frame, with world ↔ local conversion.
// Opaque materials are two-sided: the frame is flipped to the side of wo.
#pragma once

#include <memory>
#include <optional>
#include <variant>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/glints/glint_bxdf.h"
#include "glintlab/microfacet/bxdfs.h"
#include "glintlab/render/accel.h"
#include "glintlab/render/differentials.h"
#include "glintlab/scene/scene.h"

namespace glintlab {

struct ShadingFrame {
    glm::vec3 t{1, 0, 0}, b{0, 1, 0}, n{0, 0, 1};
    glm::vec3 to_local(glm::vec3 v) const {
        return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)};
    }
    glm::vec3 to_world(glm::vec3 v) const { return v.x * t + v.y * b + v.z * n; }
};

// A frame around the shading normal whose tangent follows ∂p/∂u, so that
// anisotropic roughness (αx along u) and glint grids align with the uv axes.
// With `vertex_tangent` the mesh's interpolated vertex tangent takes ∂p/∂u's
// place where the hit has one (a normal map's tangent space: smooth across
// triangles, where ∂p/∂u jumps at every edge).
ShadingFrame shading_frame(const SurfaceHit& hit, bool vertex_tangent = false);

class SurfaceBsdf {
  public:
    using Lobe = std::variant<Bxdf, GlintBxdf>;
    SurfaceBsdf(ShadingFrame frame, Lobe lobe) : frame_(frame), lobe_(std::move(lobe)) {}
    // A glint lobe whose description was resolved at this hit (textured
    // parameters): the BSDF keeps it alive.
    SurfaceBsdf(ShadingFrame frame, GlintBxdf lobe, std::shared_ptr<const GlintDesc> resolved)
        : frame_(frame), lobe_(lobe), resolved_(std::move(resolved)) {
        std::get<GlintBxdf>(lobe_).desc = resolved_.get();
    }

    glm::vec3 f(glm::vec3 wo, glm::vec3 wi) const;  // world directions
    float pdf(glm::vec3 wo, glm::vec3 wi) const;
    std::optional<BsdfSample> sample(glm::vec3 wo, float uc, glm::vec2 u) const;  // wi in world
    bool is_specular() const;
    const ShadingFrame& frame() const { return frame_; }
    // The glint description at this hit (textures resolved); null for other lobes.
    const GlintDesc* glint_desc() const {
        const GlintBxdf* g = std::get_if<GlintBxdf>(&lobe_);
        return g ? g->desc : nullptr;
    }

  private:
    ShadingFrame frame_;
    Lobe lobe_;
    std::shared_ptr<const GlintDesc> resolved_;
};

// `differentials` are the pixel's footprint and view differentials at the
// camera's first hit, null at later bounces (glint models then fall back to
// their smooth limit: docs/ARCHITECTURE.md). Textured parameters are read at
// hit.uv: their means over the footprint, or their finest level's value
// without one.
SurfaceBsdf make_surface_bsdf(const MaterialDesc& material, const SurfaceHit& hit,
                              glm::vec3 wo_world, const SurfaceDifferentials* differentials);

}  // namespace glintlab
