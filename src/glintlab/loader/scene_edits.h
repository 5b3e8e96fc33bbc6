// Edits of a scene document before the strict loader reads it: `glintlab
// render --model NAME --set POINTER=VALUE` (shared by the tools that render
// one scene under other settings). The loader then checks the edited
// document as it checks a file, so an edit cannot bypass a range or type rule.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "glintlab/scene/scene.h"

namespace glintlab {

// Sets "model" of every glint material (materials of other types keep theirs)
// and fits what the model requires (its fit_material: kneiphof2025 needs GGX,
// wang2020 Beckmann and ln N in [0, 19.4], ...), noting each change on
// stderr; an error when the scene has no glint material to switch.
void set_glint_model(nlohmann::json& document, std::string_view model);

// Sets the value at a JSON pointer (RFC 6901). The pointer's parent must
// exist; its last token may name a new object key, or an existing index or
// "-" (append) of an array. Errors name the pointer and what is missing.
void apply_override(nlohmann::json& document, std::string_view pointer,
                    const nlohmann::json& value);

// "POINTER=VALUE": VALUE is read as JSON (12, true, [1, 2], {"a": 1},
// "text") and, when it is not valid JSON, taken as a bare string (ggx).
void apply_override_assignment(nlohmann::json& document, std::string_view assignment);

struct SceneEdits {
    std::string model;              // empty: keep each material's model
    std::vector<std::string> sets;  // POINTER=VALUE, applied in order after `model`
};

// load_scene with the edits applied to the document before parsing; error
// messages name the file and JSON path as load_scene's do.
Scene load_scene(const std::filesystem::path& file, const SceneEdits& edits);

}  // namespace glintlab
