// GlintBxdf's hooks of zirr2016 (glints/glint_kernel.h).
#pragma once

#include "glintlab/glints/glint_kernel.h"
#include "glintlab/glints/zirr2016/zirr2016.h"

namespace glintlab {

struct Zirr2016Kernel : HalfVectorKernel<zirr2016_footprint_ndf> {};

}  // namespace glintlab
