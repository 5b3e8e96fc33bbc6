// Pixel footprints from ray differentials at a surface hit (pbrt-v4
// SurfaceInteraction::ComputeDifferentials): the offset rays are intersected
// with the tangent plane at the hit, and the resulting ∂p/∂x, ∂p/∂y are
// expressed in uv by least squares on (∂p/∂u, ∂p/∂v).
#pragma once

#include "glintlab/core/footprint.h"
#include "glintlab/render/accel.h"
#include "glintlab/scene/camera.h"

namespace glintlab {

struct SurfaceDifferentials {
    Footprint footprint;  // uv, duv/dx, duv/dy
    glm::vec3 dpdx{0.0f}, dpdy{0.0f};
    // The change of the unit direction towards the eye (−ray direction) per
    // pixel step: the offset rays' directions less the ray's.
    glm::vec3 dwodx{0.0f}, dwody{0.0f};
    // The pixel sample's uniform number that picks a normal map's
    // sub-footprint under "lean_mixture" (NormalMap::sample_footprint).
    float mixture_u = 0.5f;
};

// `scale` multiplies the differentials (pbrt-v4 scales camera differentials
// by max(1/8, 1/√spp) when several samples share a pixel).
SurfaceDifferentials compute_differentials(const RayDifferential& ray, const SurfaceHit& hit,
                                           float scale = 1.0f);

}  // namespace glintlab
