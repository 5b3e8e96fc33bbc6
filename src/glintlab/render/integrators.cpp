#include "glintlab/render/integrators.h"

#include <cmath>
#include <limits>
#include <variant>

#include "glintlab/core/normal_map.h"
#include "glintlab/glints/glint_lighting.h"
#include "glintlab/glints/registry.h"
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

// Whether light `light` is visible from `hit` along wi, up to t_max (the
// distance to the light from hit.p). A sphere light is a shape of the scene:
// its shadow ray stops at its own surface, where a t_max computed from hit.p
// is off by the origin offset and Embree's float sphere intersection
// (measured 1-3e-4 at distance 2, enough to self-occlude 7% of the samples
// of a glossy lobe). So for sphere lights the first hit decides: visible iff
// it is the light's own sphere, or nothing. Other lights are no shapes.
bool light_visible(const IntegratorContext& ctx, const SurfaceHit& hit, glm::vec3 wi, float t_max,
                   int light) {
    const glm::vec3 origin = offset_ray_origin(hit, wi);
    if (std::holds_alternative<SphereLight>(ctx.scene.lights[light])) {
        const auto first = ctx.accel.intersect(Ray{origin, wi}, kInfinity);
        return !first || ctx.scene.shapes[first->shape].area_light == light;
    }
    return !ctx.accel.occluded(origin, wi, t_max);
}

// The lights a glint model shades itself at the camera's first hit
// (glints/glint_lighting.h); empty for every other hit.
struct OwnLights {
    const GlintModelInfo* model = nullptr;
    const GlintDesc* desc = nullptr;
    bool has(const Scene& scene, int light) const {
        return model != nullptr && light >= 0 && model->shades_light(*desc, scene, light);
    }
};

OwnLights own_lights(const Scene& scene, const Shape& shape) {
    if (shape.material < 0) return {};
    const MaterialDesc& m = scene.materials[shape.material];
    if (m.type != MaterialDesc::Type::Glint) return {};
    const GlintModelInfo* info = find_glint_model(m.glint.model_id);
    if (info == nullptr || info->shades_light == nullptr || info->light_radiance == nullptr)
        return {};
    return {info, &m.glint};
}

// The radiance the model computes itself for its own lights.
glm::vec3 own_light_radiance(const IntegratorContext& ctx, const OwnLights& own,
                             const SurfaceHit& hit, const SurfaceBsdf& bsdf, glm::vec3 wo,
                             const Footprint& footprint, Pcg32& rng, GlintPostSample* post) {
    GlintLightingContext lc;
    lc.scene = &ctx.scene;
    // The description resolved at this hit (textured colour, base).
    lc.desc = bsdf.glint_desc() ? bsdf.glint_desc() : own.desc;
    lc.p = hit.p;
    lc.t = bsdf.frame().t;
    lc.b = bsdf.frame().b;
    lc.n = bsdf.frame().n;
    lc.wo = bsdf.frame().to_local(wo);
    lc.footprint = footprint;
    lc.rng = &rng;
    lc.post = post;
    if (lc.wo.z <= 0.0f) return glm::vec3(0.0f);
    glm::vec3 L(0.0f);
    for (int i = 0; i < static_cast<int>(ctx.scene.lights.size()); ++i) {
        if (!own.has(ctx.scene, i)) continue;
        lc.visible = [&ctx, &hit, i](glm::vec3 wi, float t_max) {
            return light_visible(ctx, hit, wi, t_max, i);
        };
        L += own.model->light_radiance(lc, i);
    }
    return L;
}

// Next-event estimation from a surface point: one sample per light, MIS
// weighted against BSDF sampling for lights that BSDF rays can hit. Lights
// in `own` are skipped (the glint model shaded them).
glm::vec3 sample_lights(const IntegratorContext& ctx, const SurfaceHit& hit,
                        const SurfaceBsdf& bsdf, glm::vec3 wo, Pcg32& rng,
                        const OwnLights& own = {}) {
    glm::vec3 L(0.0f);
    for (int i = 0; i < static_cast<int>(ctx.scene.lights.size()); ++i) {
        const Light& light = ctx.scene.lights[i];
        const glm::vec2 u = next2(rng);
        if (own.has(ctx.scene, i)) continue;
        const auto ls = sample_light(light, hit.p, u);
        if (!ls || ls->pdf <= 0.0f || ls->radiance == glm::vec3(0.0f)) continue;
        const glm::vec3 f = bsdf.f(wo, ls->wi);
        if (f == glm::vec3(0.0f)) continue;
        const float cos_i = std::abs(glm::dot(ls->wi, bsdf.frame().n));
        const float t_max = std::isinf(ls->distance) ? kInfinity : ls->distance * (1.0f - 1e-4f);
        if (!light_visible(ctx, hit, ls->wi, t_max, i)) continue;
        const float w = ls->is_delta ? 1.0f : power_heuristic(ls->pdf, bsdf.pdf(wo, ls->wi));
        L += f * ls->radiance * cos_i * w / ls->pdf;
    }
    return L;
}

// A normal map under "lean_mixture" reads one sub-footprint per pixel
// sample: the sample's own number picks it. Drawn only there, so every other
// material's random stream stays as it was.
void draw_mixture_sample(const MaterialDesc& m, Pcg32& rng, SurfaceDifferentials& diff) {
    if (m.normal_map && m.normal_map->filtering == NormalMap::Filtering::LeanMixture)
        diff.mixture_u = rng.next_float();
}

template <typename F>
bool all_finite(const F& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

glm::vec3 integrate_direct(const IntegratorContext& ctx, const RayDifferential& ray, Pcg32& rng,
                           GlintPostSample* post) {
    const Scene& scene = ctx.scene;
    const auto hit = ctx.accel.intersect(ray.ray, kInfinity);
    if (!hit) return escaped(scene, ray.ray.d, [](int) { return 1.0f; });
    glm::vec3 L = emitted(scene, *hit, ray.ray.d);
    const Shape& shape = scene.shapes[hit->shape];
    if (shape.material < 0) return L;
    SurfaceDifferentials diff = compute_differentials(ray, *hit, ctx.differential_scale);
    draw_mixture_sample(scene.materials[shape.material], rng, diff);
    const glm::vec3 wo = -ray.ray.d;
    const SurfaceBsdf bsdf = make_surface_bsdf(scene.materials[shape.material], *hit, wo, &diff);
    const OwnLights own = own_lights(scene, shape);
    if (!bsdf.is_specular()) L += sample_lights(ctx, *hit, bsdf, wo, rng, own);
    if (own.model != nullptr)
        L += own_light_radiance(ctx, own, *hit, bsdf, wo, diff.footprint, rng, post);

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
                 if (own.has(scene, i)) return 0.0f;
                 return bs->is_delta
                            ? 1.0f
                            : power_heuristic(bs->pdf, light_pdf(scene.lights[i], hit->p, bs->wi));
             });
    } else {
        const Shape& s2 = scene.shapes[hit2->shape];
        const glm::vec3 le = emitted(scene, *hit2, bs->wi);
        if (le != glm::vec3(0.0f) && !own.has(scene, s2.area_light)) {
            const float w =
                bs->is_delta ? 1.0f
                             : power_heuristic(
                                   bs->pdf, light_pdf(scene.lights[s2.area_light], hit->p, bs->wi));
            L += beta * le * w;
        }
    }
    return all_finite(L) ? L : glm::vec3(0.0f);
}

glm::vec3 integrate_path(const IntegratorContext& ctx, const RayDifferential& camera_ray,
                         Pcg32& rng, GlintPostSample* post) {
    const Scene& scene = ctx.scene;
    glm::vec3 L(0.0f), beta(1.0f);
    Ray ray = camera_ray.ray;
    bool specular_bounce = true;  // the camera ray counts as specular for MIS
    float prev_pdf = 1.0f;
    glm::vec3 prev_p(0.0f);
    OwnLights prev_own;  // lights the first hit's glint model already shaded
    for (int depth = 0;; ++depth) {
        const auto hit = ctx.accel.intersect(ray, kInfinity);
        if (!hit) {
            L += beta * escaped(scene, ray.d, [&](int i) {
                     if (prev_own.has(scene, i)) return 0.0f;
                     return specular_bounce ? 1.0f
                                            : power_heuristic(prev_pdf, light_pdf(scene.lights[i],
                                                                                  prev_p, ray.d));
                 });
            break;
        }
        const Shape& shape = scene.shapes[hit->shape];
        const glm::vec3 le = emitted(scene, *hit, ray.d);
        if (le != glm::vec3(0.0f) && !prev_own.has(scene, shape.area_light)) {
            const float w =
                specular_bounce
                    ? 1.0f
                    : power_heuristic(prev_pdf,
                                      light_pdf(scene.lights[shape.area_light], prev_p, ray.d));
            L += beta * le * w;
        }
        // max_depth counts scattering events (pbrt-v4): emission found after the
        // last one is still added above, with its MIS weight.
        if (shape.material < 0 || depth >= scene.render.max_depth) break;
        const glm::vec3 wo = -ray.d;
        // Footprints only at the camera's first hit (pbrt-v4 and 002 §4 do the
        // same): later bounces see the glint models' smooth limit.
        SurfaceDifferentials diff;
        const SurfaceDifferentials* differentials = nullptr;
        const Footprint* footprint = nullptr;
        if (depth == 0) {
            diff = compute_differentials(camera_ray, *hit, ctx.differential_scale);
            draw_mixture_sample(scene.materials[shape.material], rng, diff);
            differentials = &diff;
            footprint = &diff.footprint;
        }
        const SurfaceBsdf bsdf =
            make_surface_bsdf(scene.materials[shape.material], *hit, wo, differentials);
        const OwnLights own = depth == 0 ? own_lights(scene, shape) : OwnLights{};
        if (!bsdf.is_specular()) L += beta * sample_lights(ctx, *hit, bsdf, wo, rng, own);
        if (own.model != nullptr)
            L += beta * own_light_radiance(ctx, own, *hit, bsdf, wo, *footprint, rng, post);
        prev_own = own;

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
