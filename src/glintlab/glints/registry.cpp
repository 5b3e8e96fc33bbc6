#include "glintlab/glints/registry.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"

namespace glintlab {

// Defined by glints/model_list.cpp, from the list of models (model_list.h).
const std::vector<GlintModelDescriptor>& glint_model_list();

const char* glint_light_type_name(GlintLightType type) {
    switch (type) {
        case GlintLightType::Point:
            return "point";
        case GlintLightType::Directional:
            return "directional";
        case GlintLightType::Sphere:
            return "sphere";
        case GlintLightType::Environment:
            return "environment";
    }
    return "?";
}

const char* glint_param_type_name(GlintParamType type) {
    switch (type) {
        case GlintParamType::Number:
            return "number";
        case GlintParamType::Integer:
            return "integer";
        case GlintParamType::Bool:
            return "bool";
        case GlintParamType::Enum:
            return "enum";
    }
    return "?";
}

std::string glint_param_value_text(const GlintParamValue& value) {
    if (const double* x = std::get_if<double>(&value)) return fmt::format("{:.6g}", *x);
    if (const int* x = std::get_if<int>(&value)) return fmt::format("{}", *x);
    if (const bool* x = std::get_if<bool>(&value)) return *x ? "true" : "false";
    return std::get<std::string>(value);
}

std::string GlintParam::range_text() const {
    switch (type) {
        case GlintParamType::Bool:
            return "true or false";
        case GlintParamType::Enum:
            return fmt::format("{}", fmt::join(choices, ", "));
        case GlintParamType::Integer:
            if (!integer_values.empty()) {
                std::string s;
                for (size_t i = 0; i < integer_values.size(); ++i) {
                    if (i > 0) s += i + 1 == integer_values.size() ? " or " : ", ";
                    s += fmt::format("{}", integer_values[i]);
                }
                return s;
            }
            [[fallthrough]];
        case GlintParamType::Number:
            return NumberRange{min, max, min_open, max_open, single_precision}.text();
    }
    return "";
}

bool GlintParam::accepts(const GlintParamValue& value) const {
    switch (type) {
        case GlintParamType::Bool:
            return std::holds_alternative<bool>(value);
        case GlintParamType::Enum: {
            const std::string* s = std::get_if<std::string>(&value);
            return s && std::find(choices.begin(), choices.end(), *s) != choices.end();
        }
        case GlintParamType::Integer: {
            const int* x = std::get_if<int>(&value);
            if (!x) return false;
            if (!integer_values.empty())
                return std::find(integer_values.begin(), integer_values.end(), *x) !=
                       integer_values.end();
            return *x >= min && *x <= max;
        }
        case GlintParamType::Number: {
            const double* x = std::get_if<double>(&value);
            return x && NumberRange{min, max, min_open, max_open, single_precision}.contains(*x);
        }
    }
    return false;
}

bool GlintModelDescriptor::shades(GlintLightType type) const {
    return std::find(lights.begin(), lights.end(), type) != lights.end();
}

const GlintParam* GlintModelDescriptor::find_param(std::string_view key) const {
    for (const GlintParam& p : params)
        if (p.key == key) return &p;
    return nullptr;
}

std::span<const GlintModelDescriptor> glint_models() {
    return glint_model_list();
}

const GlintModelDescriptor* find_glint_model(std::string_view name) {
    for (const GlintModelDescriptor& m : glint_models())
        if (m.name == name) return &m;
    return nullptr;
}

const GlintModelDescriptor* find_glint_model(GlintModelId id) {
    for (const GlintModelDescriptor& m : glint_models())
        if (m.id == id) return &m;
    return nullptr;
}

const GlintModelDescriptor& glint_model(GlintModelId id) {
    const GlintModelDescriptor* m = find_glint_model(id);
    if (m == nullptr)
        fail("internal error: no descriptor for glint model id {}", static_cast<int>(id));
    return *m;
}

std::string glint_model_names() {
    std::string s;
    for (const GlintModelDescriptor& m : glint_models()) {
        if (!s.empty()) s += ", ";
        s += m.name;
    }
    return s;
}

std::string glint_models_shading(GlintLightType type) {
    std::string s;
    for (const GlintModelDescriptor& m : glint_models()) {
        if (!m.shades(type)) continue;
        if (!s.empty()) s += ", ";
        s += m.name;
    }
    return s;
}

void switch_glint_model(GlintDesc& desc, GlintModelId model) {
    const GlintModelDescriptor& m = glint_model(model);
    desc.model_id = model;
    desc.params = m.default_params();
    // The reader's rule (glint_reader.cpp): models that shade their lights
    // themselves have no diffuse base.
    if (m.shades_light != nullptr) desc.base_albedo = glm::vec3(0.0f);
    // Textures the model cannot read (glint_model_descriptor.h) give way to
    // their whole map's mean, the number a scene file would give it.
    if (desc.textures) {
        GlintTextures t = *desc.textures;
        if (!m.textured_density && t.density) {
            desc.log_density = std::log(std::max(t.density->mean(), 1e-30f));
            t.density = nullptr;
        }
        if (!m.textured_roughness && (t.alpha_x_sq || t.alpha_y_sq)) {
            if (t.alpha_x_sq)
                desc.alpha_x = std::clamp(std::sqrt(t.alpha_x_sq->mean()), 1e-3f, 1.0f);
            if (t.alpha_y_sq)
                desc.alpha_y = std::clamp(std::sqrt(t.alpha_y_sq->mean()), 1e-3f, 1.0f);
            t.alpha_x_sq = t.alpha_y_sq = nullptr;
        }
        if (m.shades_light != nullptr) t.base_albedo = nullptr;
        desc.textures = t.density || t.alpha_x_sq || t.alpha_y_sq || t.color || t.base_albedo
                            ? std::make_shared<const GlintTextures>(std::move(t))
                            : nullptr;
    }
    if (m.fit_material != nullptr) m.fit_material(desc);
}

}  // namespace glintlab
