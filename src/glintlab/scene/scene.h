// The in-memory scene: what scene files (docs/SCENE_FORMAT.md) describe,
// validated and in world space, ready for the renderers.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "glintlab/core/bloom.h"
#include "glintlab/glints/glint_desc.h"
#include "glintlab/microfacet/bxdfs.h"
#include "glintlab/scene/camera.h"
#include "glintlab/scene/environment.h"
#include "glintlab/scene/mesh.h"

namespace glintlab {

// The non-glint material parameters read from textures (scene/texture_reader.h):
// albedo (or base colour) as linear RGB, the roughness as α², metallic as
// itself. Null: the number.
struct MaterialTextures {
    std::shared_ptr<const TextureInput> albedo;
    std::shared_ptr<const TextureInput> alpha_x_sq, alpha_y_sq;
    std::shared_ptr<const TextureInput> metallic;
};

struct MaterialDesc {
    enum class Type { Diffuse, Conductor, Dielectric, Plastic, MetallicRoughness, Glint };
    std::string name;
    Type type = Type::Diffuse;
    glm::vec3 albedo{0.5f};  // Diffuse, Plastic (diffuse part), MetallicRoughness (base colour)
    float metallic = 1.0f;   // MetallicRoughness
    NdfType ndf = NdfType::GGX;
    float alpha_x = 0.2f, alpha_y = 0.2f;
    glm::vec3 eta{1.5f};  // Conductor: complex IOR; Dielectric/Plastic/MetallicRoughness: eta.x
    glm::vec3 k{0.0f};
    GlintDesc glint;                                   // Glint
    std::shared_ptr<const MaterialTextures> textures;  // null: no textured parameter
    // Every type may carry one (docs/MODELS.md, "Normal maps"); null: none.
    std::shared_ptr<const NormalMap> normal_map;
    bool needs_uv() const {
        return type == Type::Glint || textures != nullptr || normal_map != nullptr;
    }
    // Any parameter, of the glint block too, read from a texture, or a normal map.
    bool textured() const {
        return textures != nullptr || glint.textures != nullptr || normal_map != nullptr;
    }
};

// The scene format's name of a material type ("diffuse", "glint", ...).
const char* material_type_name(MaterialDesc::Type type);
// The keys of `m` read from textures ("roughness, log_density"); empty: none.
std::string textured_keys(const MaterialDesc& m);
// Throws naming the file, the material and its textured keys when `m` reads
// a parameter from a texture: `path` ("the OpenGL renderer") takes numbers only.
void require_untextured(const MaterialDesc& m, const std::filesystem::path& file, const char* path);

struct SphereGeometry {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    glm::mat3 rotation{1.0f};  // object → world rotation (orients the uv parameterization)
};

struct Shape {
    std::string name;
    std::variant<SphereGeometry, TriangleMesh> geometry;  // mesh in world space
    int material = -1;
    int area_light = -1;  // index into Scene::lights when the shape emits (sphere lights)
};

struct PointLight {
    glm::vec3 position{0.0f};
    glm::vec3 intensity{1.0f};  // W/sr
};

// Light arriving from a direction, optionally spread over a small cone of
// solid angle Ω (the sun: 6.8e-5 sr) of uniform radiance.
struct DirectionalLight {
    glm::vec3 direction{0.0f, 1.0f, 0.0f};  // unit, towards the light
    glm::vec3 irradiance{1.0f};             // W/m² on a surface facing the light
    float solid_angle = 0.0f;               // sr; 0 = delta light
    float cos_max = 1.0f;                   // cone half-angle cosine, 1 − Ω/2π
    float one_minus_cos_max = 0.0f;         // Ω/2π, exact where cos_max rounds to 1 (core/cone.h)
    glm::vec3 radiance{0.0f};               // E / (π sin²θmax) when Ω > 0
};

struct SphereLight {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    glm::vec3 radiance{1.0f};
};

struct EnvironmentLight {
    std::shared_ptr<const EnvironmentMap> map;
    std::filesystem::path file;  // empty for a constant environment
};

using Light = std::variant<PointLight, DirectionalLight, SphereLight, EnvironmentLight>;

struct RenderSettings {
    enum class Integrator { Direct, Path };
    Integrator integrator = Integrator::Path;
    int spp = 16;
    int max_depth = 8;
    int rr_depth = 3;  // Russian roulette from this depth on
    uint64_t seed = 0;
};

struct FilmSettings {
    float exposure = 0.0f;  // stops, PNG preview only (the EXR stays linear)
    BloomSettings bloom;    // applied to the PNG preview and, if set, to the EXR
    bool bloom_exr = false;
};

struct Scene {
    std::filesystem::path file;
    Camera camera;
    RenderSettings render;
    FilmSettings film;
    std::vector<MaterialDesc> materials;
    std::vector<Shape> shapes;
    std::vector<Light> lights;
    int environment = -1;  // index of the environment light, if any
};

}  // namespace glintlab
