// What a model's export hook (GlintModelExport::material, set in its
// descriptor) sees of one `glintlab export` and how it adds to the output
// (export/shader_export.h, docs/INTEGRATION.md): the exported material and
// environment, resource files with their manifest entries, and the uniforms
// the host derives from the parameters.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glintlab/glints/glint_desc.h"

namespace glintlab {

class EnvironmentMap;

struct GlintExportContext {
    // The exported material: the model's defaults, or --scene's --material.
    const GlintDesc& material;
    std::string material_name;  // "" for the model's defaults
    // The environment (--env, else --scene's); null without one.
    std::shared_ptr<const EnvironmentMap> environment;
    std::string environment_source;  // its file, or what it is
    bool resources = true;           // false with --shaders-only: write no resource
    // The manifest's "derived_uniforms": {uniform, value, from} entries.
    nlohmann::json derived_uniforms = nlohmann::json::array();

    // Writes `values` as the file "<model>.<key>.f32" (".u32") and adds
    // `info` to the manifest's resources, with the file's name, size and
    // encoding; returns that entry (valid until the next resource()).
    virtual nlohmann::json& resource(const std::string& key, const std::vector<float>& values,
                                     nlohmann::json info) = 0;
    virtual nlohmann::json& resource(const std::string& key, const std::vector<uint32_t>& values,
                                     nlohmann::json info) = 0;

    explicit GlintExportContext(const GlintDesc& m) : material(m) {}
    GlintExportContext(const GlintExportContext&) = delete;
    GlintExportContext& operator=(const GlintExportContext&) = delete;

  protected:
    ~GlintExportContext() = default;
};

}  // namespace glintlab
