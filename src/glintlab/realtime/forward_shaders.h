// GLSL of the forward renderer: one program per (glint model, light set)
// variant (the light counts are compile-time constants so loops unroll and
// uniform arrays have their exact size). Assembled from the shared .glsl
// files by core/shader_assembly: includes resolved, #line directives, so a
// driver error names the shared file and line.
#pragma once

#include <compare>
#include <string>

#include "glintlab/core/shader_assembly.h"
#include "glintlab/glints/registry.h"

namespace glintlab::gl {

struct ProgramKey {
    GlintModelId model = GlintModelId::Smooth;
    int point_lights = 0;        // point lights and sphere lights (as points, see .cpp)
    int directional_lights = 0;  // delta or cone (cone shaded at its axis)
    bool environment = false;    // image-based lighting by filtered importance sampling
    // The model's options that select another glue variant (bit i: the
    // model's GpuModelOption i, glints/gpu_model_hooks.h).
    unsigned model_options = 0;
    // The material reads parameters from textures (shaders/material_textures.glsl).
    bool material_textures = false;
    // The material has a normal map (shaders/normal_map.glsl; implies
    // material_textures: the map widens the per-fragment α).
    bool normal_map = false;
    // Its "lean_mixture" cells per axis (1: one lookup over the footprint):
    // the pass shades each of the k × k sub-footprints' lobes and averages.
    int normal_map_mixture = 1;
    // A glint material on a curved surface widens its per-fragment α by the
    // footprint's normal covariance (GLINTLAB_GLINT_CURVATURE in
    // shaders/forward.frag.glsl; implies material_textures).
    bool curvature = false;
    auto operator<=>(const ProgramKey&) const = default;
    std::string name() const;  // "forward[deliot2023, 1 point, 0 directional, no environment]"
};

// Texture units of the forward shader.
inline constexpr int kEnvironmentUnit = 0;
inline constexpr int kShadowUnit = 1;  // depth-compare 2D array, one layer per directional light
inline constexpr int kShadowMapSize = 2048;
inline constexpr int kPointShadowUnit = 2;  // depth-compare cube array, one cube per point light
inline constexpr int kPointShadowSize = 1024;
// The environment map without its bright sources (scene/environment_sources.h).
inline constexpr int kEnvironmentResidualUnit = 3;
// Textured material parameters: units kMaterialTextureUnit + slot
// (shaders/material_textures.glsl MATERIAL_TEXTURE_*).
inline constexpr int kMaterialTextureUnit = 10;  // after the models' units 4-9 (gpu_model_hooks.h)
inline constexpr int kMaterialTextureSlots = 6;
// A normal map's slopes and moments (shaders/normal_map.glsl): units 16, 17.
inline constexpr int kNormalMapUnit = kMaterialTextureUnit + kMaterialTextureSlots;

// Environment lighting (Krivanek & Colbert 2008, filtered importance
// sampling): a fixed Hammersley set of samples per pixel, the same for every
// pixel (no noise), each reading the environment without its bright sources,
// mipmapped by solid angle (scene/environment_mips.h), at the level whose
// texel solid angle matches the sample's share of the sphere: 48 of the
// lobe's visible normals and 64 cosine samples for a diffuse part. A lobe
// without one still takes kEnvironmentDefensiveSamples cosine samples: the
// lobe's own samples are too few in its tail, where each reads steradians of
// the map (a Beckmann 0.12 plane at grazing view under blender's studio map:
// +67 % without them, −6 % with). The sources (scene/environment_sources.h)
// are kEnvironmentSourceSamples directions in them.
inline constexpr int kEnvironmentSpecularSamples = 48;
inline constexpr int kEnvironmentDiffuseSamples = 64;
inline constexpr int kEnvironmentDefensiveSamples = 16;
inline constexpr int kEnvironmentSourceSamples = 32;

AssembledShader forward_vertex_shader();
AssembledShader shadow_vertex_shader();  // depth-only pass of the shadow maps
AssembledShader shadow_fragment_shader();
AssembledShader forward_fragment_shader(const ProgramKey& key);
AssembledShader background_vertex_shader();
AssembledShader background_fragment_shader();
// Full-screen tonemap (viewer display): 2^exposure, sRGB encode, clamp —
// the convention of core/image.h write_png.
AssembledShader tonemap_fragment_shader();

// Material type codes of the forward shader (u_material_type).
enum class GpuMaterialType : int {
    EmissionOnly = -1,
    Diffuse = 0,
    Conductor,
    Dielectric,
    Plastic,
    Glint,
    MetallicRoughness
};

}  // namespace glintlab::gl
