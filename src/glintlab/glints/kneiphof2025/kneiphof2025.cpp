#include "glintlab/glints/kneiphof2025/kneiphof2025.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include <glm/gtc/constants.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/glsl.h"
#include "glintlab/glints/deliot2023/deliot2023.h"
#include "glintlab/glints/glint_lighting.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"
#include "glintlab/scene/scene.h"

namespace glintlab {
namespace {

// The prefiltered environment the GLSL fetch functions read: set by the host
// for the duration of one shading call on this thread (the C++ stand-in for
// the textures a GPU back end binds).
thread_local const Kneiphof2025Environment* t_env = nullptr;

// The last fetch on this thread: one shading call reads both weight groups
// (and, for the split sum, the radiance) at the same (dir, roughness); one
// bilinear fetch serves them.
struct FetchCache {
    const Kneiphof2025Environment* env = nullptr;
    glm::vec3 dir{0.0f};
    float roughness = -1.0f;
    float values[11] = {};
};
thread_local FetchCache t_fetch;

// The pixel's stream for the area-light quadrature of one shading call (the
// jitter of kneiphof2025_cone_jitter), set by the host like t_env.
thread_local Pcg32* t_rng = nullptr;

const float* fetch_all(glm::vec3 dir, float roughness) {
    FetchCache& c = t_fetch;
    if (c.env != t_env || c.dir != dir || c.roughness != roughness) {
        t_env->fetch(dir, roughness, c.values);
        c.env = t_env;
        c.dir = dir;
        c.roughness = roughness;
    }
    return c.values;
}

}  // namespace
}  // namespace glintlab

// The only translation unit that compiles kneiphof2025.glsl as C++; its fetch
// functions read the CPU prefiltered maps (ARCHITECTURE.md §2: resources
// through fetch functions each back end defines).
GLINTLAB_SHADER_FUNCTIONS_BEGIN
vec3 kneiphof2025_radiance_fetch(vec3 dir, float roughness) {
    return t_env->fetch_radiance(dir, roughness);
}
vec4 kneiphof2025_radiance_sources_fetch(vec3 dir, float roughness) {
    return t_env->fetch_radiance_sources(dir, roughness);
}
int kneiphof2025_source_count() {
    return static_cast<int>(t_env->sources().directions.size());
}
void kneiphof2025_source(int k, vec3& direction, vec3& power, float& radius) {
    const glintlab::Kneiphof2025Sources& s = t_env->sources();
    const auto i = static_cast<size_t>(k);
    direction = s.directions[i];
    power = s.powers[i];
    radius = s.radii[i];
}
vec3 kneiphof2025_sources_color() {
    return t_env->sources().color;
}
vec4 kneiphof2025_weights_fetch(vec3 dir, float roughness, int group) {
    const float* c = fetch_all(dir, roughness);
    const int K = t_env->levels();
    vec4 w(0.0f);
    for (int i = 0; i < 4; ++i) {
        const int k = 4 * group + i;
        w[i] = k < K ? c[3 + k] : 0.0f;
    }
    return w;
}
vec3 kneiphof2025_dfg_fetch(float cos_o, float roughness) {
    return Kneiphof2025DfgLut::get().lookup(cos_o, roughness);
}
// Two draws in sequence (ring position, then sector position).
vec2 kneiphof2025_cone_jitter() {
    const float u1 = t_rng->next_float();
    const float u2 = t_rng->next_float();
    return vec2(u1, u2);
}
#include "glintlab/glints/kneiphof2025/kneiphof2025.glsl"
#include "glintlab/microfacet/fresnel.glsl"
#include "glintlab/microfacet/masking.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

// The uniform arrays of the GLSL back end hold every direction the prefilter finds.
static_assert(glintlab::Kneiphof2025Sources::kSamples == glintlab::shader::KNEIPHOF2025_SOURCES);

namespace glintlab {
namespace {

const Kneiphof2025Params& params_of(const GlintDesc& desc) {
    return std::get<Kneiphof2025Params>(desc.params);
}

float alpha_of(const GlintDesc& desc) {
    return shader::kneiphof2025_isotropic_alpha(glm::vec2(desc.alpha_x, desc.alpha_y));
}

// Solid angle of the wang2020-style cone of half-angle gamma.
float gamma_solid_angle(const Kneiphof2025Params& p) {
    return 2.0f * glm::pi<float>() * (1.0f - std::cos(glm::radians(p.gamma_deg)));
}

// An area light seen from the hit: a cone (axis, cos of its half-angle) of
// constant radiance, at distance t_max (infinity for the sun).
struct Cone {
    glm::vec3 axis;
    float cos_max;
    glm::vec3 radiance;
    float t_max;  // shadow-ray length (short of the emitter: it is geometry too)
};

// One area light (K = 1): the shared quadrature and factor of
// kneiphof2025.glsl (kneiphof2025_area_light), jittered from the pixel's
// stream, behind one shadow ray towards the cone's axis.
glm::vec3 area_light_radiance(const GlintLightingContext& ctx, const Cone& cone) {
    if (!ctx.visible(cone.axis, cone.t_max)) return glm::vec3(0.0f);
    const GlintDesc& desc = *ctx.desc;
    const Kneiphof2025Params& k = params_of(desc);
    t_rng = ctx.rng;
    const glm::vec3 L = shader::kneiphof2025_area_light(
        cone.axis, cone.cos_max, cone.radiance, ctx.t, ctx.b, ctx.n, ctx.wo, alpha_of(desc),
        kneiphof2025_f0(desc), desc.color, ctx.footprint, desc.log_density, desc.seed,
        k.microfacet_roughness, k.light_sized_area_grid, k.screen_space_scale,
        k.density_randomization, k.conditional_gaussian);
    t_rng = nullptr;
    return L;
}

}  // namespace

float kneiphof2025_total_facet_area(float alpha) {
    return shader::kneiphof2025_total_facet_area(alpha);
}

glm::vec3 kneiphof2025_f0(const GlintDesc& desc) {
    const FresnelDesc& f = desc.fresnel;
    switch (f.mode) {
        case FresnelDesc::Mode::None:
            return glm::vec3(1.0f);
        case FresnelDesc::Mode::Schlick:
            return f.f0;
        case FresnelDesc::Mode::Conductor:
            return shader::F_Conductor(1.0f, f.eta, f.k);
        case FresnelDesc::Mode::Dielectric:
            return glm::vec3(shader::F_Dielectric(1.0f, f.eta.x));
    }
    return glm::vec3(1.0f);
}

glm::vec3 kneiphof2025_environment_radiance(const Kneiphof2025Environment& env, glm::vec3 n,
                                            glm::vec3 wr, float cos_o, const Footprint& footprint,
                                            const GlintDesc& desc) {
    const Kneiphof2025Params& p = params_of(desc);
    if (env.levels() != p.levels) fail("kneiphof2025: environment prefiltered for another K");
    const auto& L = env.radiance_levels();
    t_env = &env;
    const glm::vec3 r = shader::kneiphof2025_environment(
        n, wr, cos_o, alpha_of(desc), kneiphof2025_f0(desc), desc.color, footprint,
        desc.log_density, desc.seed, p.screen_space_scale, p.density_randomization, p.levels,
        glm::vec4(L[0], L[1], L[2], L[3]), glm::vec4(L[4], L[5], L[6], L[7]),
        p.variant == Kneiphof2025Params::Variant::Wang2020Style
            ? shader::KNEIPHOF2025_VARIANT_WANG2020
            : shader::KNEIPHOF2025_VARIANT_OURS,
        gamma_solid_angle(p), p.conditional_gaussian, kneiphof2025_smooth_mode(p));
    t_env = nullptr;
    return r;
}

glm::vec3 kneiphof2025_environment_smooth(const Kneiphof2025Environment& env, glm::vec3 n,
                                          glm::vec3 wr, float cos_o, const GlintDesc& desc) {
    t_env = &env;
    const float alpha = alpha_of(desc);
    const glm::vec3 dfg = shader::kneiphof2025_dfg_fetch(cos_o, std::sqrt(alpha));
    const glm::vec3 r =
        shader::kneiphof2025_smooth_radiance(n, wr, cos_o, alpha, kneiphof2025_f0(desc), desc.color,
                                             dfg, kneiphof2025_smooth_mode(params_of(desc)));
    t_env = nullptr;
    return r;
}

int kneiphof2025_smooth_mode(const Kneiphof2025Params& p) {
    switch (p.smooth) {
        case Kneiphof2025Params::Smooth::Lobe:
            return shader::KNEIPHOF2025_SMOOTH_LOBE;
        case Kneiphof2025Params::Smooth::LobeSun:
            return shader::KNEIPHOF2025_SMOOTH_LOBE_SUN;
        case Kneiphof2025Params::Smooth::SplitSum:
            break;
    }
    return shader::KNEIPHOF2025_SMOOTH_SPLIT_SUM;
}

float kneiphof2025_area_grid_roughness(float cos_max, const Kneiphof2025Params& k) {
    return shader::kneiphof2025_area_grid_roughness(cos_max, k.microfacet_roughness,
                                                    k.light_sized_area_grid);
}

float kneiphof2025_area_factor(glm::vec3 h_center, const Footprint& footprint, float p,
                               const GlintDesc& desc, float cos_max) {
    const Kneiphof2025Params& k = params_of(desc);
    const float grid_r = kneiphof2025_area_grid_roughness(cos_max, k);
    return shader::kneiphof2025_area_factor(h_center, footprint, p, desc.log_density, desc.seed,
                                            grid_r, k.screen_space_scale, k.density_randomization,
                                            k.conditional_gaussian);
}

float kneiphof2025_binomial_factor(const Footprint& footprint, float p, const GlintDesc& desc) {
    const Kneiphof2025Params& k = params_of(desc);
    return shader::kneiphof2025_binomial_factor_no_h(footprint, p, desc.log_density, desc.seed,
                                                     k.screen_space_scale, k.density_randomization,
                                                     k.conditional_gaussian);
}

float kneiphof2025_footprint_ndf(glm::vec3 h, const Footprint& footprint, const GlintDesc& desc) {
    const Kneiphof2025Params& k = params_of(desc);
    Deliot2023Target t;
    t.ndf = shader::NDF_GGX;
    t.alpha_x = desc.alpha_x;
    t.alpha_y = desc.alpha_y;
    t.rho = desc.slope_correlation;
    t.log_density = desc.log_density;
    t.seed = desc.seed;
    Deliot2023Params d;
    d.microfacet_roughness = k.microfacet_roughness;
    d.screen_space_scale = k.screen_space_scale;
    d.density_randomization = k.density_randomization;
    d.original_defects = false;
    d.conditional_gaussian = k.conditional_gaussian;
    return deliot2023_ndf(h, footprint, t, d);
}

bool kneiphof2025_shades_light(const GlintDesc&, const Scene& scene, int light) {
    const Light& l = scene.lights[static_cast<size_t>(light)];
    if (std::holds_alternative<EnvironmentLight>(l) || std::holds_alternative<SphereLight>(l))
        return true;
    if (const auto* d = std::get_if<DirectionalLight>(&l)) return d->solid_angle > 0.0f;
    return false;  // point lights: GlintBxdf (deliot2023's D_P)
}

glm::vec3 kneiphof2025_light_radiance(const GlintLightingContext& ctx, int light) {
    const Light& l = ctx.scene->lights[static_cast<size_t>(light)];
    const GlintDesc& desc = *ctx.desc;
    if (ctx.wo.z <= 0.0f) return glm::vec3(0.0f);
    if (const auto* e = std::get_if<EnvironmentLight>(&l)) {
        // 003 §7: unshadowed (occlusion of the environment is future work, §8).
        const Kneiphof2025Params& p = params_of(desc);
        const auto env = kneiphof2025_environment_for(e->map, p.levels, p.black_level);
        const glm::vec3 wr = ctx.to_world(glm::vec3(-ctx.wo.x, -ctx.wo.y, ctx.wo.z));
        return kneiphof2025_environment_radiance(*env, ctx.n, wr, ctx.wo.z, ctx.footprint, desc);
    }
    if (const auto* s = std::get_if<SphereLight>(&l)) {
        const glm::vec3 d = s->center - ctx.p;
        const float dist = glm::length(d);
        if (!(dist > s->radius)) return glm::vec3(0.0f);
        const float sin_max = s->radius / dist;
        Cone c{d / dist, std::sqrt(std::max(0.0f, 1.0f - sin_max * sin_max)), s->radiance,
               (dist - s->radius) * (1.0f - 1e-4f)};
        return area_light_radiance(ctx, c);
    }
    if (const auto* dl = std::get_if<DirectionalLight>(&l)) {
        if (!(dl->solid_angle > 0.0f)) return glm::vec3(0.0f);
        Cone c{glm::normalize(dl->direction), dl->cos_max, dl->radiance,
               std::numeric_limits<float>::infinity()};
        return area_light_radiance(ctx, c);
    }
    return glm::vec3(0.0f);
}

}  // namespace glintlab
