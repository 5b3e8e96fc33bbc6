#include "glintlab/render/integrators.h"

#include <cmath>
#include <limits>

#include "glintlab/render/differentials.h"
#include "glintlab/render/light_sampling.h"
#include "glintlab/render/surface_bsdf.h"

namespace glintlab {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

float power_heuristic(float pdf_a, float pdf_b) {
    const float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    if (std::isinf(a)) return 1.0f;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

glm::vec2 next2(Pcg32& rng) {
    const float a = rng.next_float();
    return {a, rng.next_float()};
}

// Radiance reaching a ray that escapes the scene: environment and sun cones.
// `weight_light(i)` gives the MIS weight for light i.
template <typename Weight>
glm::vec3 escaped(const Scene& scene, glm::vec3 dir, Weight weight_light) {
    glm::vec3 L(0.0f);
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const glm::vec3 le = escaped_radiance(scene.lights[i], dir);
        if (le != glm::vec3(0.0f)) L += le * weight_light(static_cast<int>(i));
    }
    return L;
}

// Emitted radiance of a hit shape towards -dir (sphere lights emit outwards).
glm::vec3 emitted(const Scene& scene, const SurfaceHit& hit, glm::vec3 dir) {
    const Shape& shape = scene.shapes[hit.shape];
    if (shape.area_light < 0 || glm::dot(hit.ng, dir) >= 0.0f) return glm::vec3(0.0f);
    return std::get<SphereLight>(scene.lights[shape.area_light]).radiance;
}

// Next-event estimation from a surface point: one sample per light, MIS
// weighted against BSDF sampling for lights that BSDF rays can hit.
glm::vec3 sample_lights(const IntegratorContext& ctx, const SurfaceHit& hit,
                        const SurfaceBsdf& bsdf, glm::vec3 wo, Pcg32& rng) {
    glm::vec3 L(0.0f);
    for (const Light& light : ctx.scene.lights) {
        const glm::vec2 u = next2(rng);
        const auto ls = sample_light(light, hit.p, u);
        if (!ls || ls->pdf <= 0.0f || ls->radiance == glm::vec3(0.0f)) continue;
        const glm::vec3 f = bsdf.f(wo, ls->wi);
        if (f == glm::vec3(0.0f)) continue;
        const float cos_i = std::abs(glm::dot(ls->wi, bsdf.frame().n));
        const glm::vec3 origin = offset_ray_origin(hit, ls->wi);
        const float t_max = std::isinf(ls->distance) ? kInfinity : ls->distance * (1.0f - 1e-4f);
        if (ctx.accel.occluded(origin, ls->wi, t_max)) continue;
        const float w = ls->is_delta ? 1.0f : power_heuristic(ls->pdf, bsdf.pdf(wo, ls->wi));
        L += f * ls->radiance * cos_i * w / ls->pdf;
    }
    return L;
}

template <typename F>
bool all_finite(const F& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

glm::vec3 integrate_direct(const IntegratorContext& ctx, const RayDifferential& ray, Pcg32& rng) {
    const Scene& scene = ctx.scene;
    const auto hit = ctx.accel.intersect(ray.ray, kInfinity);
    if (!hit) return escaped(scene, ray.ray.d, [](int) { return 1.0f; });
    glm::vec3 L = emitted(scene, *hit, ray.ray.d);
    const Shape& shape = scene.shapes[hit->shape];
    if (shape.material < 0) return L;
    const SurfaceDifferentials diff = compute_differentials(ray, *hit, ctx.differential_scale);
    const glm::vec3 wo = -ray.ray.d;
    const SurfaceBsdf bsdf =
        make_surface_bsdf(scene.materials[shape.material], *hit, wo, &diff.footprint);
    if (!bsdf.is_specular()) L += sample_lights(ctx, *hit, bsdf, wo, rng);

    // One BSDF sample: MIS partner of light sampling for lights with area,
    // the only estimator for specular lobes.
    const float uc = rng.next_float();
    const glm::vec2 u = next2(rng);
    const auto bs = bsdf.sample(wo, uc, u);
    if (!bs || bs->pdf <= 0.0f || bs->f == glm::vec3(0.0f)) return L;
    const glm::vec3 beta = bs->f * std::abs(glm::dot(bs->wi, bsdf.frame().n)) / bs->pdf;
    const Ray next{offset_ray_origin(*hit, bs->wi), bs->wi};
    const auto hit2 = ctx.accel.intersect(next, kInfinity);
    if (!hit2) {
        L += beta * escaped(scene, bs->wi, [&](int i) {
                 return bs->is_delta ? 1.0f
                                     : power_heuristic(bs->pdf, light_pdf(scene.lights[i], hit->p, bs->wi));
             });
    } else {
        const Shape& s2 = scene.shapes[hit2->shape];
        const glm::vec3 le = emitted(scene, *hit2, bs->wi);
        if (le != glm::vec3(0.0f)) {
            const float w = bs->is_delta ? 1.0f
                                         : power_heuristic(bs->pdf, light_pdf(scene.lights[s2.area_light],
                                                                              hit->p, bs->wi));
            L += beta * le * w;
        }
    }
    return all_finite(L) ? L : glm::vec3(0.0f);
}

glm::vec3 integrate_path(const IntegratorContext& ctx, const RayDifferential& camera_ray,
                         Pcg32& rng) {
    const Scene& scene = ctx.scene;
    glm::vec3 L(0.0f), beta(1.0f);
    Ray ray = camera_ray.ray;
    bool specular_bounce = true;  // the camera ray counts as specular for MIS
    float prev_pdf = 1.0f;
    glm::vec3 prev_p(0.0f);
    for (int depth = 0;; ++depth) {
        const auto hit = ctx.accel.intersect(ray, kInfinity);
        if (!hit) {
            L += beta * escaped(scene, ray.d, [&](int i) {
                     return specular_bounce ? 1.0f
                                            : power_heuristic(prev_pdf, light_pdf(scene.lights[i], prev_p, ray.d));
                 });
            break;
        }
        const Shape& shape = scene.shapes[hit->shape];
        const glm::vec3 le = emitted(scene, *hit, ray.d);
        if (le != glm::vec3(0.0f)) {
            const float w = specular_bounce
                                ? 1.0f
                                : power_heuristic(prev_pdf, light_pdf(scene.lights[shape.area_light], prev_p, ray.d));
            L += beta * le * w;
        }
        // max_depth counts scattering events (pbrt-v4): emission found after the
        // last one is still added above, with its MIS weight.
        if (shape.material < 0 || depth >= scene.render.max_depth) break;
        const glm::vec3 wo = -ray.d;
        // Footprints only at the camera's first hit (pbrt-v4 and 002 §4 do the
        // same): later bounces see the glint models' smooth limit.
        SurfaceDifferentials diff;
        const Footprint* footprint = nullptr;
        if (depth == 0) {
            diff = compute_differentials(camera_ray, *hit, ctx.differential_scale);
            footprint = &diff.footprint;
        }
        const SurfaceBsdf bsdf = make_surface_bsdf(scene.materials[shape.material], *hit, wo, footprint);
        if (!bsdf.is_specular()) L += beta * sample_lights(ctx, *hit, bsdf, wo, rng);

        const float uc = rng.next_float();
        const glm::vec2 u = next2(rng);
        const auto bs = bsdf.sample(wo, uc, u);
        if (!bs || bs->pdf <= 0.0f || bs->f == glm::vec3(0.0f)) break;
        beta *= bs->f * std::abs(glm::dot(bs->wi, bsdf.frame().n)) / bs->pdf;
        specular_bounce = bs->is_delta;
        prev_pdf = bs->pdf;
        prev_p = hit->p;
        ray = Ray{offset_ray_origin(*hit, bs->wi), bs->wi};
        if (!all_finite(beta)) break;
        // Russian roulette (pbrt-v4): survive with probability max component of beta.
        if (depth + 1 >= scene.render.rr_depth) {
            const float q = std::max(0.0f, 1.0f - std::max({beta.x, beta.y, beta.z}));
            if (rng.next_float() < q) break;
            beta /= 1.0f - q;
        }
    }
    return all_finite(L) ? L : glm::vec3(0.0f);
}

}  // namespace glintlab
