// A tangent-space normal map as the renderers read it (docs/MODELS.md,
// "Normal maps"): its texels turned into slopes and LEAN-mapped (Olano &
// Baker, "LEAN Mapping", I3D 2010): mip chains hold the first moments
// (s_x, s_y) and the second moments (s_x², s_y², s_x s_y) of the slopes, so
// the filtered lookup over a pixel footprint gives the footprint's mean
// slope and its slope covariance Σ = E[s sᵀ] − s̄ s̄ᵀ.
//
// Slopes follow the microfacet convention (Heitz 2014 Eq. 36): a unit
// normal n = (x, y, z) in the tangent frame (x along ∂p/∂u, y along the
// map's "up", z the surface normal) has slope s = (−x/z, −y/z), and
// n = normalize(−s_x, −s_y, 1).
#pragma once

#include <memory>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/core/texture_input.h"

namespace glintlab {

// The unit normal of slope s: normalize(−s_x, −s_y, 1).
inline glm::vec3 normal_from_slope(glm::vec2 s) {
    return glm::normalize(glm::vec3(-s.x, -s.y, 1.0f));
}

// The footprint's slope statistics: mean slope and covariance (symmetric,
// positive semi-definite; xx, yy, xy).
struct SlopeStatistics {
    glm::vec2 mean{0.0f};
    glm::vec3 covariance{0.0f};
    glm::vec3 normal() const { return normal_from_slope(mean); }
};

struct NormalMap {
    // "lean": the footprint's mean normal and slope covariance (the filtered
    // models widen their NDF by it); "lean_mixture": the same over one of
    // mixture × mixture sub-footprints, picked per pixel sample, so the
    // samples average a mixture of lobes, each with its own mean normal
    // (one Gaussian lobe misses a footprint whose normals are far from one
    // Gaussian: docs/MODELS.md, "Normal maps"); "none": the finest level's
    // normal at the pixel's centre, no covariance (the per-pixel normal
    // mapping of a forward renderer: the aliasing the filter removes stays
    // measurable).
    enum class Filtering { Lean, LeanMixture, None };
    Filtering filtering = Filtering::Lean;
    int mixture = 1;  // sub-footprints per footprint axis (LeanMixture)
    // Channels s_x, s_y, s_x², s_y²: the mean and the variances in one
    // lookup, all a glint or anisotropic lobe reads.
    std::shared_ptr<const TextureInput> slopes;
    // Channel s_x s_y: read only where Σ's correlation matters (an
    // isotropic lobe, rotated to Σ's principal axes).
    std::shared_ptr<const TextureInput> cross_moment;

    // The statistics over the footprint at uv (the finest level's bilinear
    // values without a footprint, or with Filtering::None). covariance.z,
    // the correlation, only where `correlated` (one more chain lookup),
    // otherwise 0.
    SlopeStatistics lookup(glm::vec2 uv, const Footprint* footprint, bool correlated = false) const;
    // The footprint a lookup reads for the pixel sample whose uniform
    // number is u in [0, 1): under LeanMixture the cell floor(u · mixture²)
    // of the footprint's mixture × mixture grid (footprint_cell), otherwise
    // `footprint`. The OpenGL renderer shades every cell and averages.
    Footprint sample_footprint(const Footprint& footprint, float u) const;
    // The finest level's bilinear slope at uv (the ground truth's per-facet normal).
    glm::vec2 slope_at(glm::vec2 uv) const;

  private:
    // The weight of the mip chain's statistics at the footprint's λ
    // (core/slope_frame.glsl lean_chain_weight; the rest is the finest
    // level's own surface).
    float chain_weight(const Footprint& fp) const;
};

// A tangent frame around the unit normal n whose tangent is the projection
// of (1, 0, 0) (the base frame's ∂p/∂u direction): the frame a normal map
// rotates a local lobe into. Returns (t, b) with b = n × t.
void tangent_frame_around(glm::vec3 n, glm::vec3* t, glm::vec3* b);

}  // namespace glintlab
