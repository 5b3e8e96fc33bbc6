// The viewer's model panel without GL: one widget per row of the active
// model's parameter table (key, type, range, current value, setter). The
// viewer (realtime/viewer.cpp) draws it with ImGui; tests check it against
// the descriptors (GlintPanelModel.*).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {

struct GlintPanelWidget {
    std::string key;
    GlintParamType type = GlintParamType::Number;
    GlintParamUi ui = GlintParamUi::Linear;
    // Number / Integer: the slider's ends (an open end is moved inside by
    // one float step, so every slider position is accepted).
    double min = 0.0, max = 0.0;
    std::vector<std::string> choices;  // Enum names, or the allowed integers as text
    std::vector<int> integer_values;   // Integer with a list of allowed values
    GlintParamValue value;             // current value in the material
    // Writes a value into the material's params; values outside the range
    // are clamped (numbers, integers) or ignored (unknown choices).
    std::function<void(const GlintParamValue&)> set;
};

// An editable RGB colour list of the model (a descriptor extra key):
// `*count` entries of `colours`, in [0, 1], count in [0, max_count].
struct GlintPanelColours {
    std::string key;
    int max_count = 0;
    int* count = nullptr;
    glm::vec3* colours = nullptr;
};

// Widgets of desc's active model; setters write into desc.params (desc must
// outlive them).
std::vector<GlintPanelWidget> glint_panel_model(GlintDesc& desc);
// The model's colour lists, pointing into desc.params.
std::vector<GlintPanelColours> glint_panel_colours(GlintDesc& desc);

}  // namespace glintlab
