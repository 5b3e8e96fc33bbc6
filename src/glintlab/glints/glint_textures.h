// Textured glint parameters at a surface point (docs/MODELS.md, "Textured
// parameters"): the footprint means of the textures' filtered quantities,
// turned back into the numbers every model reads — ln of the mean density,
// the square root of the mean α², the mean colour. Without a footprint (a
// path's later bounces) the finest level's bilinear value at the point.
#pragma once

#include "glintlab/core/footprint.h"
#include "glintlab/glints/glint_desc.h"

namespace glintlab {

// `desc` with its textured parameters replaced by their values at `uv` over
// `footprint` (may be null). The textures stay attached (the ground truth
// reads them per facet).
GlintDesc resolve_glint_textures(const GlintDesc& desc, glm::vec2 uv, const Footprint* footprint);

// α from a filtered α², within the glint materials' range [1e-3, 1].
float alpha_from_squared(float alpha_sq);

}  // namespace glintlab
