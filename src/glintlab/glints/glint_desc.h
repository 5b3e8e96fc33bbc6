// The glint material as the renderers see it (ARCHITECTURE.md, "Materials and
// the glint material"): the parameters every model shares plus the active
// model's own block. Each fact is held once: the model is `model_id` (its
// name and everything else about it come from its descriptor,
// glint_model_descriptor.h), its parameters are `params`.
#pragma once

#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "glintlab/core/normal_map.h"
#include "glintlab/core/texture_input.h"
#include "glintlab/glints/model_list.h"
#include "glintlab/glints/model_params.h"
#include "glintlab/microfacet/bxdfs.h"

namespace glintlab {

// The models, expanded from the list of models (model_list.h) in its order,
// from Smooth = 0 (a new model is appended: the existing values stay).
// GlintBxdf dispatches on it (static, no strings in the hot path).
enum class GlintModelId : int {
#define GLINTLAB_MODEL_ID(m, M) M,
    GLINTLAB_GLINT_MODELS(GLINTLAB_MODEL_ID)
#undef GLINTLAB_MODEL_ID
};
// The number of models: of GlintModelId values, GlintModelParams
// alternatives and descriptors.
inline constexpr int kGlintModelCount = GLINTLAB_GLINT_MODEL_COUNT;

// The light types of the scene format; a model's descriptor lists those it
// can shade and the scene loader rejects the others.
enum class GlintLightType : int { Point = 0, Directional, Sphere, Environment };
inline constexpr GlintLightType kGlintLightTypes[] = {
    GlintLightType::Point, GlintLightType::Directional, GlintLightType::Sphere,
    GlintLightType::Environment};
// "point", "directional", "sphere", "environment": the scene format's names.
const char* glint_light_type_name(GlintLightType type);

// How a material computes Fresnel reflectance.
struct FresnelDesc {
    enum class Mode { None, Schlick, Conductor, Dielectric };
    Mode mode = Mode::None;  // None: F = 1 (jakob2014's default for metallic flakes)
    glm::vec3 f0{1.0f};      // Schlick
    glm::vec3 eta{1.0f};     // Conductor (complex IOR eta + i k) or Dielectric (eta.x)
    glm::vec3 k{0.0f};
};

// The glint parameters read from textures (docs/MODELS.md, "Textured
// parameters"), each mip-mapped in the quantity a footprint averages: the
// density N = e^{ln N} (facets per unit uv area: a footprint's expected
// count is its integral), α² (slope variance), linear RGB. Null: the
// parameter is the material's number.
struct GlintTextures {
    std::shared_ptr<const TextureInput> density;
    std::shared_ptr<const TextureInput> alpha_x_sq, alpha_y_sq;
    std::shared_ptr<const TextureInput> color, base_albedo;
};

struct GlintDesc {
    GlintModelId model_id = GlintModelId::Smooth;
    NdfType ndf = NdfType::Beckmann;
    float alpha_x = 0.3f, alpha_y = 0.3f;
    float log_density = 20.0f;  // ln(microfacets per unit uv area)
    FresnelDesc fresnel;
    glm::vec3 color{1.0f};  // glint tint, multiplies the BRDF
    // Lambertian base under the flakes' dielectric coating (002 Fig. 7's
    // "dielectric flakes on a diffuse base"); 0 = none. Needs a dielectric
    // Fresnel: its eta is the coating interface (glint_bxdf.h).
    glm::vec3 base_albedo{0.0f};
    bool has_base() const { return base_albedo != glm::vec3(0.0f); }
    uint32_t seed = 0;
    // Textured parameters (null: none). The renderers resolve them at each
    // hit (glint_textures.h) into the numbers above; the ground truth
    // `explicit` also reads them per facet.
    std::shared_ptr<const GlintTextures> textures;
    // The material's normal map as the ground truth reads it: each facet's
    // normal composed with the map's normal at the facet's own position
    // (docs/MODELS.md, "Normal maps"). Set by the renderers at each hit for
    // `explicit` only; the other models see a frame and a roughness that
    // already hold the map. `normal_map_axes` maps the map's (x, y) onto the
    // hit's local frame: (1, ±1) on the front (−1 where the uv mapping is
    // mirrored), x negated too seen from behind.
    std::shared_ptr<const NormalMap> normal_map;
    glm::vec2 normal_map_axes{1.0f};
    // The pixel's wo in that local frame: each facet's map normal is turned
    // to face it as the models' mean normal is (core/slope_frame.glsl
    // visible_slope); 0: not turned.
    glm::vec3 normal_map_view{0.0f};
    // Set where the renderers resolved α per hit (a roughness map, a normal
    // map's widening): every pixel may hold another α, and models that
    // build a table per α (jakob2014) snap it to a grid instead.
    bool alpha_varies = false;
    // The surface's own turning over a footprint (the material's
    // "curvature" key; docs/MODELS.md, "Curved surfaces"): true
    // ("footprint"), `explicit` composes each facet with the macro normal at
    // its own position and the filtered models widen their NDF by the
    // footprint's normal covariance; false ("none", the default), one normal
    // per footprint.
    bool curvature = false;
    // Set by the renderers at each hit for `explicit` only: the macro normal's
    // slope (microfacet convention, normal_map.h) as a linear function of the
    // uv offset from the footprint's centre, columns ∂s/∂u and ∂s/∂v in the
    // hit's local frame. Zero: a flat footprint.
    glm::mat2 slope_gradient{0.0f};
    // Set by the renderers at each hit for the models whose descriptor
    // reads it: the correlation of the footprint's slopes, Σ_xy / (σ_x σ_y)
    // with σ_i² = α_i²/2 of the widened α, in [−0.99, 0.99].
    float slope_correlation = 0.0f;
    // The active model's parameters, as read through its descriptor's
    // parameter table. (The block as written in the scene file is not kept:
    // nothing needs it once it is read, and a second copy could disagree.)
    GlintModelParams params;
};

}  // namespace glintlab
