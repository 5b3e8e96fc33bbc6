// The one translation unit that compiles the shared counting laws as C++
// (see laws.h).
#include "glintlab/counting/laws.h"

GLINTLAB_SHADER_BEGIN
#include "glintlab/counting/binomial_laws.glsl"
#include "glintlab/counting/distributed_binomial.glsl"
#include "glintlab/counting/multinomial.glsl"
GLINTLAB_SHADER_END
