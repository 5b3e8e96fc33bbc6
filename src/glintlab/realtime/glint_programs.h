// The glint model of a forward program: the GLSL glue file beside the model
// (glints/<model>/<model>_gpu.glsl) that includes the model's shared .glsl
// (never a GPU-only copy) and exposes it to the forward shader as
//     vec3 glint_ndf(vec3 h, Footprint fp);  // D_P(h), RGB
// (the rest of the BRDF, Fresnel, G2, the base, is glints/material.glsl).
// Which glue, and the C++ that feeds the model's uniforms and resources,
// come from the model's GpuModelHooks (glints/gpu_model_hooks.h): this file
// names no model.
#pragma once

#include <string>

#include "glintlab/glints/gpu_model_hooks.h"
#include "glintlab/glints/registry.h"

namespace glintlab {

struct GlintDesc;

namespace gl {

// The embedded path of the model's glue file for the mask of its options
// that change the program, and the GLSL line including it (resolved by
// assemble_shader). Throws glintlab::Error for a model the GPU renderer does
// not implement, naming the models it does.
std::string glint_model_glue_path(GlintModelId model, unsigned program_options = 0);
std::string glint_model_glsl(GlintModelId model, unsigned program_options = 0);

// Whether the GPU renderer implements `model`.
bool gpu_supports_model(GlintModelId model);

}  // namespace gl
}  // namespace glintlab
