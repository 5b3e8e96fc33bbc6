#include "glintlab/glints/glint_reader.h"

#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/glints/registry.h"

namespace glintlab {

GlintModelId read_glint_model_name(JsonObject& material) {
    const std::string name = material.required_string("model");
    const GlintModelDescriptor* model = find_glint_model(name);
    if (model == nullptr)
        material.error("model", fmt::format("unknown glint model \"{}\": known models are {}", name,
                                            glint_model_names()));
    return model->id;
}

void read_glint_params(const GlintModelDescriptor& model, JsonObject& block, GlintDesc& desc) {
    desc.params = model.default_params();
    for (const GlintParam& p : model.params) {
        block.ignore(p.key);  // known even when absent: an unknown key's error lists it
        if (!block.has(p.key)) continue;
        GlintParamValue value;
        switch (p.type) {
            case GlintParamType::Number: {
                NumberRange r{p.min, p.max, p.min_open, p.max_open, p.single_precision};
                value = block.number(p.key, 0.0, r);
                break;
            }
            case GlintParamType::Integer: {
                const nlohmann::json& v = *block.raw(p.key);
                if (!v.is_number_integer())
                    block.error(p.key, fmt::format("expected an integer {}, got {}", p.range_text(),
                                                   v.dump()));
                const auto x = v.get<int64_t>();
                if (x < p.min || x > p.max || !p.accepts(static_cast<int>(x)))
                    block.error(
                        p.key, fmt::format("value {} out of range: allowed {}", x, p.range_text()));
                value = static_cast<int>(x);
                break;
            }
            case GlintParamType::Bool:
                value = block.boolean(p.key, false);
                break;
            case GlintParamType::Enum:
                if (!block.raw(p.key)->is_string())
                    block.error(p.key, fmt::format("expected one of {}, got {}", p.range_text(),
                                                   block.raw(p.key)->dump()));
                value = block.string(p.key, "", p.choices);
                break;
        }
        p.set(desc.params, value);
    }
    for (const GlintExtraKey& k : model.extra_keys) block.ignore(k.key);
    if (model.check != nullptr) model.check(block, desc);
    block.finish();
}

void read_glint_model_blocks(JsonObject& material, GlintDesc& desc) {
    const GlintModelDescriptor& model = glint_model(desc.model_id);
    if ((desc.has_base() || (desc.textures && desc.textures->base_albedo)) &&
        model.shades_light != nullptr)
        material.error("base_albedo",
                       fmt::format("glint model \"{}\" shades its lights itself (prefiltered or "
                                   "enumerated radiance) and has no diffuse base; use another "
                                   "model or omit base_albedo",
                                   model.name));
    // Every known model may keep its block (switching models is one word);
    // only the active one is read, the others are checked to be objects.
    for (const GlintModelDescriptor& m : glint_models()) {
        material.ignore(m.name);
        if (!material.has(m.name)) continue;
        auto block = material.object(m.name);
        if (m.id == model.id) read_glint_params(model, *block, desc);
    }
    if (!material.has(model.name)) {
        const nlohmann::json empty = nlohmann::json::object();
        JsonObject block(empty, material.path() + "/" + std::string(model.name), material.file());
        read_glint_params(model, block, desc);
    }
}

std::string_view glint_model_name(GlintModelId id) {
    return glint_model(id).name;
}

bool glint_model_shades(GlintModelId id, GlintLightType type) {
    return glint_model(id).shades(type);
}

std::string glint_models_shading_names(GlintLightType type) {
    return glint_models_shading(type);
}

}  // namespace glintlab
