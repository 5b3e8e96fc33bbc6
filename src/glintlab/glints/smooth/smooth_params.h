// Parameters of the smooth model: none of its own (its material is the glint
// material's shared parameters).
#pragma once

namespace glintlab {

struct SmoothParams {};

}  // namespace glintlab
