// The JSON front end of the glint model descriptors: the scene loader reads a
// glint material's shared keys itself and hands the model's name and blocks
// to these functions, which go through the model's descriptor (its parameter
// table and check hook). The scene side sees model ids and light types only,
// never the model list.
#pragma once

#include <string>
#include <string_view>

#include "glintlab/glints/glint_desc.h"

namespace glintlab {

class JsonObject;
struct GlintModelDescriptor;

// Reads the material's "model" (required); the error lists the known models.
GlintModelId read_glint_model_name(JsonObject& material);

// Reads the active model's block (absent = defaults) through its descriptor,
// checks the other models' blocks are objects (switching models is one word),
// and applies model rules on the shared keys (a diffuse base needs a model
// that is a BRDF). desc.model_id and the shared keys must be read already.
void read_glint_model_blocks(JsonObject& material, GlintDesc& desc);

// The generic reader of one model's block: every row of the parameter table
// (type and range checked, errors naming file, JSON path, key and range),
// then the descriptor's check hook, then unknown keys are rejected.
void read_glint_params(const GlintModelDescriptor& model, JsonObject& block, GlintDesc& desc);

std::string_view glint_model_name(GlintModelId id);
bool glint_model_shades(GlintModelId id, GlintLightType type);
// "a, b, c": the models that can shade `type` (from their descriptors).
std::string glint_models_shading_names(GlintLightType type);

}  // namespace glintlab
