// The closed list of glint models (ARCHITECTURE.md §5): name → what the model
// supports and how its own parameter block is read. Later issues add models
// here; the scene parser and the CLI list them from this table.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

namespace glintlab {

class JsonObject;
struct GlintDesc;
struct GlintLightingContext;
struct Scene;

// Models in registry order; GlintBxdf dispatches on it (static, no strings
// in the hot path).
// Ids of models still being built are listed ahead of their registry row.
enum class GlintModelId : int {
    Smooth = 0,
    Deliot2023,
    Zirr2016,
    Chermain2020,
    Explicit,
    Jakob2014,
    Kneiphof2025,
    Wang2020,
};

struct GlintModelInfo {
    GlintModelId id;
    std::string_view name;
    std::string_view description;
    // Light types the model can shade; the scene loader rejects the others.
    bool point_lights;
    bool directional_lights;
    bool sphere_lights;
    bool environment_lights;
    // Reads (and range-checks) the model's parameter block into desc.params
    // and calls block.finish().
    void (*read_params)(JsonObject& block, GlintDesc& desc);
    // Optional (glint_lighting.h): whether the model shades scene.lights[light]
    // itself at the camera's first hit, and that light's reflected radiance
    // towards ctx.wo. Null for models that are plain BRDFs (GlintBxdf) under
    // every light.
    bool (*shades_light)(const GlintDesc& desc, const Scene& scene, int light) = nullptr;
    glm::vec3 (*light_radiance)(const GlintLightingContext& ctx, int light) = nullptr;
};

std::span<const GlintModelInfo> glint_models();
const GlintModelInfo* find_glint_model(std::string_view name);
const GlintModelInfo* find_glint_model(GlintModelId id);
std::string glint_model_names();  // "a, b, c" for error messages

}  // namespace glintlab
