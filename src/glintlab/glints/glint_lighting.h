// Models that light the camera's first hit themselves (ARCHITECTURE.md,
// "Materials and the glint material"):
// the explicit ground truth sums each facet's mirror reflection of the lights
// and of the environment, the image-based-lighting models (kneiphof2025,
// wang2020) combine prefiltered radiance with their own counting. Such a model
// fills GlintModelInfo::shades_light / light_radiance (registry.h); the
// integrators then call light_radiance for those lights at the first hit
// instead of next-event estimation, and give those lights zero weight when a
// BSDF-sampled ray from the first hit finds them (that light is already
// counted). Indirect light and later bounces use the model's smooth limit.
#pragma once

#include <functional>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/core/rng.h"

namespace glintlab {

struct GlintDesc;
struct Scene;

// Radiance a model hands to a screen-space pass instead of returning it
// (wang2020 §4.4: the glint layer and its directional occlusion are blurred
// over the image). The renderer averages the samples of each pixel, runs the
// pass and adds its result to the image (render/renderer.cpp).
struct GlintPostSample {
    glm::vec3 rgb{0.0f};      // radiance to post-process, without occlusion
    float visibility = 1.0f;  // directional occlusion of this sample, 0 or 1
    bool active = false;      // whether a model wrote this sample
};

struct GlintLightingContext {
    const Scene* scene = nullptr;
    const GlintDesc* desc = nullptr;
    glm::vec3 p{0.0f};  // world position of the hit
    // Shading frame in world space (z = n; t follows ∂p/∂u, see surface_bsdf.h).
    glm::vec3 t{1, 0, 0}, b{0, 1, 0}, n{0, 0, 1};
    glm::vec3 wo{0, 0, 1};  // local direction towards the camera, wo.z > 0
    Footprint footprint{};  // pixel footprint in uv (always present here)
    // True when the world direction `wi` from the hit reaches distance
    // `t_max` (infinity for lights at infinity) without being blocked.
    std::function<bool(glm::vec3 wi, float t_max)> visible;
    Pcg32* rng = nullptr;  // for models that estimate by sampling
    // Null where no image pass follows (e.g. validation calls): models then
    // return all their radiance.
    GlintPostSample* post = nullptr;

    glm::vec3 to_local(glm::vec3 v) const {
        return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)};
    }
    glm::vec3 to_world(glm::vec3 v) const { return v.x * t + v.y * b + v.z * n; }
};

}  // namespace glintlab
