// The model list (glints/model_list.h, .cpp) and lookups over it. Front ends loop
// over glint_models() and name no model.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {

// Every model's descriptor, in GlintModelId order (model_list.cpp).
std::span<const GlintModelDescriptor> glint_models();
const GlintModelDescriptor* find_glint_model(std::string_view name);
const GlintModelDescriptor* find_glint_model(GlintModelId id);
const GlintModelDescriptor& glint_model(GlintModelId id);  // every id has one
std::string glint_model_names();                           // "a, b, c" for error messages
// "a, b, c": the models whose descriptors list `type`.
std::string glint_models_shading(GlintLightType type);

// Switches a material to `model` with the model's default parameters, fitted
// by the model's fit_material (e.g. the NDF it requires): the viewer's model
// switcher and tests that render one scene with every model.
void switch_glint_model(GlintDesc& desc, GlintModelId model);

}  // namespace glintlab
