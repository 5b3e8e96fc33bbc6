// GlintBxdf's hooks of deliot2023 (glints/glint_kernel.h).
#pragma once

#include "glintlab/glints/deliot2023/deliot2023.h"
#include "glintlab/glints/glint_kernel.h"

namespace glintlab {

struct Deliot2023Kernel : HalfVectorKernel<deliot2023_footprint_ndf> {};

}  // namespace glintlab
