// The mip chain of a lat-long environment map, each coarser texel the
// solid-angle-weighted mean of the texels it covers. A GPU's own mip
// generation averages texels with equal weights, which counts a texel near a
// pole (solid angle ∝ sin θ) as much as one at the horizon: a sun 7° from
// the zenith then weighs 1/sin 7° ≈ 8× too much in the coarse levels that
// wide filtered-importance samples read (the GPU's smooth material under
// such maps was 1.2–2.2× too bright).
#pragma once

#include <vector>

#include "glintlab/core/image.h"

namespace glintlab {

// Levels 0 (the image itself) to 1 × 1, each level's size that of OpenGL's
// mip chain (halved and floored, at least 1). A coarse texel is the mean of
// the finer level over its own solid angle: each fine texel it overlaps
// weighs by the overlap's solid angle ((u overlap) × (cos θ overlap)), so
// odd sizes, whose coarse texels cut fine ones, keep the map's power and a
// constant map stays constant.
std::vector<Image> latlong_mip_chain(const Image& level0);

}  // namespace glintlab
