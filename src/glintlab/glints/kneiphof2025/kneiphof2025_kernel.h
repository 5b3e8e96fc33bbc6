// GlintBxdf's hooks of kneiphof2025 (glints/glint_kernel.h). The lights it
// shades itself go through its descriptor's light_radiance.
#pragma once

#include "glintlab/glints/glint_kernel.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025.h"

namespace glintlab {

struct Kneiphof2025Kernel : HalfVectorKernel<kneiphof2025_footprint_ndf> {};

}  // namespace glintlab
