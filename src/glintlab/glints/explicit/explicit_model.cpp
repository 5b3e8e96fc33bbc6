#include "glintlab/glints/explicit/explicit_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "glintlab/core/cone.h"
#include "glintlab/core/error.h"
#include "glintlab/glints/glint_bxdf.h"
#include "glintlab/glints/glint_lighting.h"
#include "glintlab/scene/environment.h"
#include "glintlab/scene/scene.h"

namespace glintlab {
namespace {

const ExplicitParams& params_of(const GlintDesc& desc) {
    static const ExplicitParams kDefaults;
    const auto* p = std::get_if<ExplicitParams>(&desc.params);
    return p != nullptr ? *p : kDefaults;
}

// A cone of directions (world space) with uniform radiance.
struct Cone {
    glm::vec3 axis;
    float one_minus_cos_max;  // core/cone.h
    glm::vec3 radiance;
};

glm::vec3 cone_radiance(const GlintLightingContext& ctx, const Cone& cone) {
    const GlintDesc& desc = *ctx.desc;
    const ExplicitFacetField field = explicit_field(desc, ctx.footprint);
    const Footprint fp = explicit_enumerated_footprint(field, ctx.footprint);
    const double area = explicit_footprint_area(fp);
    if (!(area > 0.0)) return glm::vec3(0.0f);
    const glm::vec3 axis = ctx.to_local(cone.axis);
    GlintBxdf bxdf;
    bxdf.desc = &desc;
    glm::dvec3 sum(0.0);
    for_each_explicit_facet(field, fp, [&](const ExplicitFacet& f) {
        glm::vec3 r;
        const float w = explicit_facet_weight(field, ctx.wo, f, r);
        if (w <= 0.0f || !inside_cone(r, axis, cone.one_minus_cos_max)) return;
        sum += glm::dvec3(w * f.weight * bxdf.fresnel(glm::dot(ctx.wo, f.m)));
    });
    if (sum == glm::dvec3(0.0)) return glm::vec3(0.0f);
    const double n = double(explicit_facets_per_tile(field));
    return desc.color * cone.radiance * glm::vec3(sum / (n * area));
}

}  // namespace

ExplicitFacetField explicit_field(const GlintDesc& desc, const Footprint& footprint) {
    ExplicitFacetField f;
    f.ndf = desc.ndf;
    f.alpha_x = desc.alpha_x;
    f.alpha_y = desc.alpha_y;
    f.log_density = desc.log_density;
    f.seed = desc.seed;
    f.max_facets_per_footprint = params_of(desc).max_facets_per_footprint;
    f.subsample_over_budget = params_of(desc).subsample_over_budget;
    if (desc.textures) {
        f.textures = desc.textures.get();
        if (const auto& density = desc.textures->density) {
            // Generated at the map's largest density, thinned per facet.
            const double n_max = std::max(1.0, std::ceil(double(density->max_value())));
            f.log_density = std::log(n_max);
        }
    }
    f.normal_map = desc.normal_map.get();
    f.normal_map_axes = desc.normal_map_axes;
    f.normal_map_view = desc.normal_map_view;
    f.slope_gradient = desc.slope_gradient;
    f.slope_origin = footprint.uv;
    return f;
}

float explicit_gamma_rad(const GlintDesc& desc) {
    return params_of(desc).gamma_deg * std::numbers::pi_v<float> / 180.0f;
}

float explicit_footprint_ndf(glm::vec3 wo, glm::vec3 wi, const Footprint& footprint,
                             const GlintDesc& desc) {
    const ExplicitFacetField field = explicit_field(desc, footprint);
    return explicit_footprint_ndf(field, explicit_enumerated_footprint(field, footprint), wo, wi,
                                  explicit_gamma_rad(desc));
}

bool explicit_shades_light(const GlintDesc&, const Scene&, int) {
    return true;  // every light type (explicit_model.h)
}

glm::vec3 explicit_light_radiance(const GlintLightingContext& ctx, int light) {
    const Light& l = ctx.scene->lights[static_cast<size_t>(light)];
    const GlintDesc& desc = *ctx.desc;
    if (ctx.wo.z <= 0.0f) return glm::vec3(0.0f);
    const float inf = std::numeric_limits<float>::infinity();
    if (const auto* e = std::get_if<EnvironmentLight>(&l)) {
        GlintBxdf bxdf;
        bxdf.desc = &desc;
        const EnvironmentMap& map = *e->map;
        // Each facet's mirror direction is occluded or not (one shadow ray
        // per lit facet): the truth is the smooth BRDF's reflection of the
        // visible environment, ∫ f V L cos dwi, as the integrators' light
        // sampling computes it for every other BSDF. Without V, concave or
        // self-shadowing shapes (the compare blob) were too bright.
        const ExplicitFacetField field = explicit_field(desc, ctx.footprint);
        const glm::vec3 L = explicit_environment_radiance(
            field, explicit_enumerated_footprint(field, ctx.footprint), ctx.wo,
            [&](glm::vec3 r) {
                const glm::vec3 d = ctx.to_world(r);
                const glm::vec3 le = map.eval(d);
                if (le == glm::vec3(0.0f) || (ctx.visible && !ctx.visible(d, inf)))
                    return glm::vec3(0.0f);
                return le;
            },
            [&](float cos_om) { return bxdf.fresnel(cos_om); });
        return desc.color * L;
    }
    if (const auto* s = std::get_if<SphereLight>(&l)) {
        const glm::vec3 d = s->center - ctx.p;
        const float dist = glm::length(d);
        if (!(dist > s->radius)) return glm::vec3(0.0f);
        const glm::vec3 axis = d / dist;
        if (ctx.visible && !ctx.visible(axis, (dist - s->radius) * (1.0f - 1e-4f)))
            return glm::vec3(0.0f);
        const float sin_max = s->radius / dist;
        return cone_radiance(ctx, {axis, one_minus_cos_from_sin2(sin_max * sin_max), s->radiance});
    }
    const float gamma = explicit_gamma_rad(desc);
    const float sigma = float(explicit_cone_solid_angle(gamma));
    const float gamma_one_minus_cos = 2.0f * std::sin(0.5f * gamma) * std::sin(0.5f * gamma);
    if (const auto* dl = std::get_if<DirectionalLight>(&l)) {
        const glm::vec3 axis = glm::normalize(dl->direction);
        if (ctx.visible && !ctx.visible(axis, inf)) return glm::vec3(0.0f);
        if (dl->solid_angle > 0.0f)
            return cone_radiance(ctx, {axis, dl->one_minus_cos_max, dl->radiance});
        return cone_radiance(ctx, {axis, gamma_one_minus_cos, dl->irradiance / sigma});
    }
    if (const auto* pl = std::get_if<PointLight>(&l)) {
        const glm::vec3 d = pl->position - ctx.p;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return glm::vec3(0.0f);
        const float dist = std::sqrt(dist2);
        const glm::vec3 axis = d / dist;
        if (ctx.visible && !ctx.visible(axis, dist * (1.0f - 1e-4f))) return glm::vec3(0.0f);
        return cone_radiance(ctx, {axis, gamma_one_minus_cos, pl->intensity / (dist2 * sigma)});
    }
    return glm::vec3(0.0f);
}

}  // namespace glintlab
