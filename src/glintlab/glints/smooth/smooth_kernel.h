// GlintBxdf's hooks of the smooth model (glints/glint_kernel.h): none,
// D_P = D, the smooth limit every model falls back to.
#pragma once

namespace glintlab {

struct SmoothKernel {};

}  // namespace glintlab
