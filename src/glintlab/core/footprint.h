// C++ view of the footprint contract (core/footprint.glsl).
#pragma once

#include "glintlab/core/glsl.h"

GLINTLAB_SHADER_BEGIN
#include "glintlab/core/footprint.glsl"
GLINTLAB_SHADER_END

namespace glintlab {
using Footprint = shader::Footprint;
}
