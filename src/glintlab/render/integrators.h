// The two CPU integrators (ARCHITECTURE.md "Rendering"):
//  - direct: the first hit, lit once per light per sample (light sampling with
//    MIS against BSDF sampling for lights with area), plus emitters and the
//    environment seen directly or through one BSDF sample: what a real-time
//    shader computes, so its images compare with the GPU's.
//  - path: unidirectional path tracing with next-event estimation on every
//    light, MIS (power heuristic), environment importance sampling and
//    Russian roulette: the reference.
#pragma once

#include <glm/glm.hpp>

#include "glintlab/core/rng.h"
#include "glintlab/glints/glint_lighting.h"
#include "glintlab/render/accel.h"
#include "glintlab/scene/camera.h"
#include "glintlab/scene/scene.h"

namespace glintlab {

struct IntegratorContext {
    const Scene& scene;
    const Accelerator& accel;
    float differential_scale = 1.0f;
};

// `post`, when given, receives the radiance a glint model defers to an image
// pass at the camera's first hit (glints/glint_lighting.h, GlintPostSample);
// that radiance is then not in the returned value.
glm::vec3 integrate_direct(const IntegratorContext& ctx, const RayDifferential& ray, Pcg32& rng,
                           GlintPostSample* post = nullptr);
glm::vec3 integrate_path(const IntegratorContext& ctx, const RayDifferential& ray, Pcg32& rng,
                         GlintPostSample* post = nullptr);

}  // namespace glintlab
