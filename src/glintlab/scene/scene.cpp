#include "glintlab/scene/scene.h"

#include "glintlab/core/error.h"

namespace glintlab {

const char* material_type_name(MaterialDesc::Type type) {
    switch (type) {
        case MaterialDesc::Type::Diffuse:
            return "diffuse";
        case MaterialDesc::Type::Conductor:
            return "conductor";
        case MaterialDesc::Type::Dielectric:
            return "dielectric";
        case MaterialDesc::Type::Plastic:
            return "plastic";
        case MaterialDesc::Type::MetallicRoughness:
            return "metallic_roughness";
        case MaterialDesc::Type::Glint:
            return "glint";
    }
    return "unknown";
}

std::string textured_keys(const MaterialDesc& m) {
    std::string keys;
    auto add = [&](bool on, const char* key) {
        if (on) keys += keys.empty() ? key : std::string(", ") + key;
    };
    if (m.textures) {
        add(m.textures->albedo != nullptr,
            m.type == MaterialDesc::Type::MetallicRoughness ? "base_color" : "albedo");
        add(m.textures->alpha_x_sq || m.textures->alpha_y_sq, "roughness");
        add(m.textures->metallic != nullptr, "metallic");
    }
    if (m.glint.textures) {
        const GlintTextures& t = *m.glint.textures;
        add(t.alpha_x_sq || t.alpha_y_sq, "roughness");
        add(t.density != nullptr, "log_density");
        add(t.color != nullptr, "color");
        add(t.base_albedo != nullptr, "base_albedo");
    }
    add(m.normal_map != nullptr, "normal_map");
    return keys;
}

void require_untextured(const MaterialDesc& m, const std::filesystem::path& file,
                        const char* path) {
    if (!m.textured()) return;
    fail(
        "{}: material \"{}\" reads {} from a texture: {} takes numbers only (textured "
        "parameters render in glintlab render, with or without --gpu, view, compare and Python; "
        "an exported shader reads the host's own textures through its per-pixel inputs, "
        "docs/INTEGRATION.md \"Per-pixel material inputs\": export the material with numbers)",
        file.string(), m.name, textured_keys(m), path);
}

}  // namespace glintlab
