// C++ view of the shared hash functions (core/hash.glsl).
#pragma once

#include "glintlab/core/glsl.h"

GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/core/constants.glsl"
#include "glintlab/core/hash.glsl"
GLINTLAB_SHADER_FUNCTIONS_END
