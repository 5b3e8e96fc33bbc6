// Documentation generated from the model descriptors: `glintlab info --json`
// and `glintlab info --markdown SECTION`, and the sections of docs/MODELS.md
// and docs/SCENE_FORMAT.md between
//   <!-- BEGIN generated: glintlab info --markdown SECTION -->
//   <!-- END generated -->
// (regenerate with `glintlab info --update-docs docs/MODELS.md docs/SCENE_FORMAT.md`;
// ModelDocs.GeneratedDocSectionsAreCurrent fails when they drift).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace glintlab {

struct GlintModelDescriptor;

// A descriptor as JSON: name, description, citations, lights, back ends,
// parameters (key, type, default, range with open/closed ends, unit, doc,
// choices), extra keys, texture inputs, validation suite.
nlohmann::json glint_model_to_json(const GlintModelDescriptor& model);

// The glint material keys a model reads from a texture (docs/MODELS.md,
// "Textured parameters"), in the scene format's order; with its reason for
// the keys it does not read (empty when it reads them all).
struct GlintTextureInputs {
    std::vector<std::string> keys, refused;
    std::string reason;
};
GlintTextureInputs glint_texture_inputs(const GlintModelDescriptor& model);

// The sections `glintlab info --markdown` prints.
std::vector<std::string>
model_doc_sections();  // "models", "parameters", "citations", "scene-format"
// Throws (listing the sections) for an unknown name.
std::string model_doc_markdown(std::string_view section);

// `text` with the content of every generated section replaced by its
// current generation; throws on an unknown section or a BEGIN without END.
std::string update_generated_sections(const std::string& text, const std::string& file);

}  // namespace glintlab
