#include "glintlab/render/light_sampling.h"

#include <cmath>
#include <limits>

#include <glm/gtc/constants.hpp>

#include "glintlab/core/cone.h"

namespace glintlab {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

float cone_pdf(float one_minus_cos_max) {
    return 1.0f / (glm::two_pi<float>() * one_minus_cos_max);
}

// 1 − cos θmax of the cone a sphere subtends from distance² dc2.
float sphere_one_minus_cos_max(float r2, float dc2) {
    return one_minus_cos_from_sin2(r2 / dc2);
}

}  // namespace

void orthonormal_basis(glm::vec3 n, glm::vec3* t, glm::vec3* b) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    *t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

glm::vec3 sample_uniform_cone(glm::vec2 u, float one_minus_cos_max) {
    const float one_minus_cos = u.x * one_minus_cos_max;
    const float cos_theta = 1.0f - one_minus_cos;
    const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
    const float phi = u.y * glm::two_pi<float>();
    return {std::cos(phi) * sin_theta, std::sin(phi) * sin_theta, cos_theta};
}

std::optional<LightSample> sample_light(const Light& light, glm::vec3 p, glm::vec2 u) {
    LightSample s;
    if (const auto* l = std::get_if<PointLight>(&light)) {
        const glm::vec3 d = l->position - p;
        const float r2 = glm::dot(d, d);
        if (r2 == 0.0f) return std::nullopt;
        s.distance = std::sqrt(r2);
        s.wi = d / s.distance;
        s.radiance = l->intensity / r2;
        s.pdf = 1.0f;
        s.is_delta = true;
        return s;
    }
    if (const auto* l = std::get_if<DirectionalLight>(&light)) {
        s.distance = kInfinity;
        if (l->solid_angle <= 0.0f) {
            s.wi = l->direction;
            s.radiance = l->irradiance;
            s.pdf = 1.0f;
            s.is_delta = true;
            return s;
        }
        glm::vec3 t, b;
        orthonormal_basis(l->direction, &t, &b);
        const glm::vec3 c = sample_uniform_cone(u, l->one_minus_cos_max);
        s.wi = glm::normalize(c.x * t + c.y * b + c.z * l->direction);
        s.radiance = l->radiance;
        s.pdf = cone_pdf(l->one_minus_cos_max);
        return s;
    }
    if (const auto* l = std::get_if<SphereLight>(&light)) {
        const glm::vec3 to_center = l->center - p;
        const float dc2 = glm::dot(to_center, to_center);
        const float r2 = l->radius * l->radius;
        if (dc2 <= r2) return std::nullopt;  // inside the light: no direct contribution sampled
        const float dc = std::sqrt(dc2);
        const glm::vec3 axis = to_center / dc;
        const float one_minus_cos_max = sphere_one_minus_cos_max(r2, dc2);
        glm::vec3 t, b;
        orthonormal_basis(axis, &t, &b);
        const glm::vec3 c = sample_uniform_cone(u, one_minus_cos_max);
        s.wi = glm::normalize(c.x * t + c.y * b + c.z * axis);
        // Distance to the near intersection with the sphere along wi.
        const float proj = glm::dot(to_center, s.wi);
        const float disc = std::max(0.0f, r2 - (dc2 - proj * proj));
        s.distance = proj - std::sqrt(disc);
        s.radiance = l->radiance;
        s.pdf = cone_pdf(one_minus_cos_max);
        return s;
    }
    const auto& env = std::get<EnvironmentLight>(light);
    s.radiance = env.map->sample(u, &s.wi, &s.pdf);
    if (s.pdf <= 0.0f) return std::nullopt;
    s.distance = kInfinity;
    return s;
}

float light_pdf(const Light& light, glm::vec3 p, glm::vec3 wi) {
    if (const auto* l = std::get_if<DirectionalLight>(&light)) {
        if (l->solid_angle <= 0.0f) return 0.0f;
        return inside_cone(wi, l->direction, l->one_minus_cos_max) ? cone_pdf(l->one_minus_cos_max)
                                                                   : 0.0f;
    }
    if (const auto* l = std::get_if<SphereLight>(&light)) {
        const glm::vec3 to_center = l->center - p;
        const float dc2 = glm::dot(to_center, to_center);
        const float r2 = l->radius * l->radius;
        if (dc2 <= r2) return 0.0f;
        const float one_minus_cos_max = sphere_one_minus_cos_max(r2, dc2);
        return inside_cone(wi, to_center / std::sqrt(dc2), one_minus_cos_max)
                   ? cone_pdf(one_minus_cos_max)
                   : 0.0f;
    }
    if (const auto* l = std::get_if<EnvironmentLight>(&light)) return l->map->pdf(wi);
    return 0.0f;
}

glm::vec3 escaped_radiance(const Light& light, glm::vec3 dir) {
    if (const auto* l = std::get_if<DirectionalLight>(&light)) {
        if (l->solid_angle > 0.0f && inside_cone(dir, l->direction, l->one_minus_cos_max))
            return l->radiance;
        return glm::vec3(0.0f);
    }
    if (const auto* l = std::get_if<EnvironmentLight>(&light)) return l->map->eval(dir);
    return glm::vec3(0.0f);
}

}  // namespace glintlab
