// C++ view of the view differentials (core/view_differentials.glsl).
#pragma once

#include "glintlab/core/glsl.h"

GLINTLAB_SHADER_BEGIN
#include "glintlab/core/view_differentials.glsl"
GLINTLAB_SHADER_END

namespace glintlab {
using ViewDifferentials = shader::ViewDifferentials;
}
