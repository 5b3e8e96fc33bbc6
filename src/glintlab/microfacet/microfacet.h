// C++ view of the shared smooth-microfacet shading code (ndf, masking, fresnel,
// visible-normal sampling): the same .glsl files the GPU back ends compile.
#pragma once

#include "glintlab/core/glsl.h"

GLINTLAB_SHADER_BEGIN
#include "glintlab/core/constants.glsl"
// The .glsl functions are plain (non-inline) definitions; an unnamed namespace
// gives them internal linkage so that several translation units may include
// this header. Unused ones would warn, hence the pragma.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace {
#include "glintlab/microfacet/erf.glsl"
#include "glintlab/microfacet/fresnel.glsl"
#include "glintlab/microfacet/masking.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/microfacet/vndf.glsl"
}  // namespace
#pragma GCC diagnostic pop
GLINTLAB_SHADER_END
