// The GPU host part of each glint model: the GLSL glue file beside the model
// (glints/<model>/<model>_gpu.glsl) that includes the model's shared .glsl
// (never a GPU-only copy) and exposes it to the forward shader as
//     vec3 glint_ndf(vec3 h, Footprint fp);  // D_P(h), RGB
// (the rest of the BRDF, Fresnel, G2, the base, is glints/material.glsl)
// and the C++ that feeds its uniforms and resources (chermain2020's
// dictionary texture) from a GlintDesc. These mirror, term for term, what
// glints/glint_bxdf.cpp evaluates on the CPU.
#pragma once

#include <string>
#include <vector>

#include "glintlab/glints/registry.h"

namespace glintlab {

struct GlintDesc;

namespace gl {

class UniformCache;

// The embedded path of the model's glue file, and the GLSL line including it
// (resolved by assemble_shader).
// Throws glintlab::Error for a model the GPU renderer does not implement.
// `noise_texture` (deliot2023 only): the uniforms of the gated-Gaussian
// evaluations come from a 64 x 64 RG32F noise texture (000 §6.3, the
// shared file's GLINTLAB_DELIOT2023_NOISE_TEXTURE variant) instead of two
// hash rounds.
std::string glint_model_glue_path(GlintModelId model, bool noise_texture = false);
std::string glint_model_glsl(GlintModelId model, bool noise_texture = false);

// Whether the GPU renderer implements `model`.
bool gpu_supports_model(GlintModelId model);

// Texture units 0..3 are the forward shader's (see forward_shaders.h);
// models use units from 4 on.
inline constexpr int kFirstModelTextureUnit = 4;

// GPU resources of the models (created on first use in the
// current context, freed with this object).
class GlintResources {
  public:
    GlintResources();
    ~GlintResources();
    GlintResources(const GlintResources&) = delete;
    GlintResources& operator=(const GlintResources&) = delete;
    // Binds what `model` needs to its texture units.
    void bind(GlintModelId model, bool noise_texture = false);

  private:
    unsigned chermain2020_dictionary_ = 0;  // R32F texture, uploaded lazily
    unsigned deliot2023_noise_ = 0;         // RG32F 64 x 64, uploaded lazily
};

// Sets the model's uniforms of `program` from the material.
void set_glint_uniforms(unsigned program, UniformCache& uniforms, const GlintDesc& desc);

// The 64 x 64 uniform pairs of the deliot2023 noise texture, row-major,
// flattened: deliot2023_noise_table(), the CPU's own table.
std::vector<float> deliot2023_noise_pairs();

// Default parameters of `model` (the viewer's model switcher).
void reset_model_params(GlintDesc& desc, GlintModelId model);

}  // namespace gl
}  // namespace glintlab
