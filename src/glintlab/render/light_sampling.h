// Sampling and evaluation of the scene's lights for next-event estimation and
// multiple importance sampling (pbrt-v4 Light::SampleLi / PDF_Li / Le).
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "glintlab/scene/scene.h"

namespace glintlab {

struct LightSample {
    glm::vec3 radiance{0.0f};  // incident radiance (delta lights: intensity/r² or irradiance)
    glm::vec3 wi{0.0f};        // unit direction from the shading point to the light
    float distance = 0.0f;     // to the light along wi (infinity for distant lights)
    float pdf = 0.0f;          // solid-angle pdf; 1 for delta lights
    bool is_delta = false;
};

std::optional<LightSample> sample_light(const Light& light, glm::vec3 p, glm::vec2 u);

// Solid-angle pdf with which sample_light would have produced direction wi
// from p, for lights a BSDF-sampled ray can hit (sphere, cone, environment).
float light_pdf(const Light& light, glm::vec3 p, glm::vec3 wi);

// Radiance of distant lights (environment, directional cones) seen along an escaping ray.
glm::vec3 escaped_radiance(const Light& light, glm::vec3 dir);

// Uniform direction in the cone around z with 1 − cos θmax = one_minus_cos_max
// (core/cone.h: exact for cones below ~1.5e-7 sr).
glm::vec3 sample_uniform_cone(glm::vec2 u, float one_minus_cos_max);
// Orthonormal basis (t, b, n) with n given (Duff et al. 2017).
void orthonormal_basis(glm::vec3 n, glm::vec3* t, glm::vec3* b);

}  // namespace glintlab
