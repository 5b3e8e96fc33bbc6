#include "glintlab/glints/wang2020/wang2020_model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "glintlab/core/error.h"
#include "glintlab/glints/glint_lighting.h"
#include "glintlab/glints/model_params.h"
#include "glintlab/glints/wang2020/wang2020_shading.h"
#include "glintlab/scene/environment.h"
#include "glintlab/scene/scene.h"

namespace glintlab {

namespace {

using wang2020::UvBox;
using wang2020::Wang2020Material;
using wang2020::Wang2020Model;

const Wang2020Params& params_of(const GlintDesc& desc) {
    return std::get<Wang2020Params>(desc.params);
}

uint64_t particles_of(const GlintDesc& desc) {
    return wang2020_particles(desc.log_density);
}

// One model per (material, environment map); the map pointer identifies the
// environment (scenes own their maps for the whole render).
using Key = std::tuple<float, float, uint64_t, uint32_t, double, int, int, int, int, bool, bool,
                       bool, bool, bool, std::array<float, 10>, const EnvironmentMap*>;

// The Fresnel of M (001 Eq. 11) is inside the prefiltered tables.
std::array<float, 10> fresnel_key(const FresnelDesc& f) {
    return {static_cast<float>(f.mode),
            f.f0.x,
            f.f0.y,
            f.f0.z,
            f.eta.x,
            f.eta.y,
            f.eta.z,
            f.k.x,
            f.k.y,
            f.k.z};
}

// The map pointer is part of the key; the entry also keeps a weak_ptr to the
// map so that a new map allocated at a freed map's address (a later scene)
// never reuses the old prefiltered tables.
struct CacheEntry {
    std::weak_ptr<const EnvironmentMap> env;
    bool has_env = false;
    std::shared_ptr<const Wang2020Model> model;
    uint64_t last_use = 0;
};

using ModelCache = std::map<Key, CacheEntry>;

// The cache keeps the models of the most recently used materials only: the
// seed is part of the key (the particles are the seed's), so a sweep over
// seeds (compare's realizations, a Python sweep) made one model per seed
// and kept them all — 24 GB after a few hundred realizations of an
// environment scene (`validate compare` was killed for memory). Renderers
// hold their model by shared_ptr, so an evicted entry lives on until its
// last render ends; the bound only costs a rebuild when more materials
// than this alternate. Entries of a freed map are dropped at once (their
// tables can never be used again).
constexpr size_t kMaxCachedModels = 4;

void evict_stale_models(ModelCache& cache, const Key& keep) {
    for (auto it = cache.begin(); it != cache.end();) {
        if (!(it->first == keep) && it->second.has_env && it->second.env.expired())
            it = cache.erase(it);
        else
            ++it;
    }
    while (cache.size() > kMaxCachedModels) {
        auto oldest = cache.end();
        for (auto it = cache.begin(); it != cache.end(); ++it)
            if (!(it->first == keep) &&
                (oldest == cache.end() || it->second.last_use < oldest->second.last_use))
                oldest = it;
        if (oldest == cache.end()) break;
        cache.erase(oldest);
    }
}

// A cached model of the same material and environment with another seed:
// its tables are the ones this key needs (they never depend on the seed),
// so only the quadtree is built (Wang2020Model::with_seed). Without it
// every realization of a compare row rebuilt the prefiltered tables, ~2 s
// each at 48x48, and `validate compare` spent over 30 min re-running
// wang2020 on its first scene.
const Wang2020Model* model_with_other_seed(const ModelCache& cache, const Key& key) {
    Key unseeded = key;
    std::get<3>(unseeded) = 0;
    for (const auto& [k, entry] : cache) {
        Key other = k;
        std::get<3>(other) = 0;
        if (!(other == unseeded) || !entry.model) continue;
        if (entry.has_env && entry.env.expired()) continue;
        return entry.model.get();
    }
    return nullptr;
}

// A cached model of the same material built for any live environment map:
// lights other than the environment read no prefiltered table, so it serves
// them. Without this a scene's environment and its other lights kept two
// entries per material, and four materials (the robustness suite's) thrashed
// the bounded cache: a quadtree rebuilt per evaluation, the suite's wang2020
// share past 7 minutes instead of about 2.
CacheEntry* entry_with_any_environment(ModelCache& cache, const Key& key) {
    Key bare = key;
    std::get<15>(bare) = nullptr;
    for (auto& [k, entry] : cache) {
        Key other = k;
        std::get<15>(other) = nullptr;
        if (!(other == bare) || !entry.model) continue;
        if (entry.has_env && entry.env.expired()) continue;
        return &entry;
    }
    return nullptr;
}

std::shared_ptr<const Wang2020Model> model_for(const GlintDesc& desc,
                                               const std::shared_ptr<const EnvironmentMap>& env) {
    static std::mutex mutex;
    static ModelCache cache;
    const Wang2020Params& p = params_of(desc);
    const Key key{desc.alpha_x,
                  0.0f,
                  particles_of(desc),
                  desc.seed,
                  p.gamma_deg,
                  p.depth,
                  p.dpf_theta,
                  p.dpf_phi,
                  p.prefilter_samples,
                  p.micro_per_particle,
                  p.prefilter_mis,
                  p.dpf_exact_roughness,
                  p.scale_count_effective,
                  p.particle_radiance_point,
                  fresnel_key(desc.fresnel),
                  env.get()};
    const std::lock_guard lock(mutex);
    static uint64_t uses = 0;
    if (!env)
        if (CacheEntry* any = entry_with_any_environment(cache, key)) {
            any->last_use = ++uses;
            return any->model;
        }
    CacheEntry& slot = cache[key];
    slot.last_use = ++uses;
    if (slot.model && env && slot.env.expired()) slot.model = nullptr;
    // Called per shading call: a hit is a lookup only; the cache can only
    // outgrow its bound, or hold a freed map's entry worth dropping, after
    // a miss.
    const bool miss = !slot.model;
    if (!slot.model) {
        if (const Wang2020Model* sibling = model_with_other_seed(cache, key)) {
            slot.model = sibling->with_seed(desc.seed);
            slot.env = env;
            slot.has_env = env != nullptr;
        }
    }
    if (!slot.model) {
        Wang2020Material m;
        // The loader accepts the documented [0.02, 1] as written; the float
        // 0.02f lies 4e-10 below the decimal 0.02 the tables start at.
        m.alpha = std::clamp(static_cast<double>(desc.alpha_x), 0.02, 1.0);
        m.gamma_deg = p.gamma_deg;
        m.particles = particles_of(desc);
        m.depth = p.depth;
        m.seed = desc.seed;
        m.color = glm::dvec3(1.0);  // the tint is applied per call
        m.fresnel = desc.fresnel;
        m.scale_count = p.scale_count_effective ? wang2020::ScaleCount::Effective
                                                : wang2020::ScaleCount::Particles;
        m.particle_radiance = p.particle_radiance_point ? wang2020::ParticleRadiance::Point
                                                        : wang2020::ParticleRadiance::Cone;
        m.dpf_res = {p.dpf_theta, p.dpf_theta, p.dpf_phi};
        m.prefilter_samples = p.prefilter_samples;
        m.micro = p.micro_per_particle ? wang2020::MicroMode::PerParticle
                                       : wang2020::MicroMode::AsPublished;
        m.prefilter =
            p.prefilter_mis ? wang2020::PrefilterMode::Mis : wang2020::PrefilterMode::AsPublished;
        m.dpf_roughness = p.dpf_exact_roughness ? wang2020::DpfRoughness::Exact
                                                : wang2020::DpfRoughness::Interpolated;
        auto model = std::make_shared<Wang2020Model>(m);
        if (env) {
            const EnvironmentMap* map = env.get();
            wang2020::EnvironmentSampler sampler;
            sampler.sample = [map](const glm::dvec2& u, glm::dvec3& dir) {
                glm::vec3 d(0.0f);
                float pdf = 0.0f;
                map->sample(glm::vec2(u), &d, &pdf);
                dir = glm::dvec3(d);
                return static_cast<double>(pdf);
            };
            sampler.pdf = [map](const glm::dvec3& d) {
                return static_cast<double>(map->pdf(glm::vec3(d)));
            };
            model->prefilter([map](const glm::dvec3& d) { return map->eval(glm::vec3(d)); },
                             &sampler, map->image().height);
        }
        slot.model = std::move(model);
        slot.env = env;
        slot.has_env = env != nullptr;
    }
    std::shared_ptr<const Wang2020Model> result = slot.model;
    if (miss) evict_stale_models(cache, key);  // invalidates `slot`
    return result;
}

// AABB of the footprint parallelogram uv + s duvdx + t duvdy, s, t ∈ [-½, ½),
// with the parallelogram itself (UvBox).
UvBox box_of(const Footprint& fp) {
    const glm::dvec2 half = 0.5 * (glm::abs(glm::dvec2(fp.duvdx)) + glm::abs(glm::dvec2(fp.duvdy)));
    return {glm::dvec2(fp.uv) - half, glm::dvec2(fp.uv) + half, glm::dvec2(fp.uv),
            glm::dvec2(fp.duvdx), glm::dvec2(fp.duvdy)};
}

}  // namespace

std::shared_ptr<const wang2020::Wang2020Model> wang2020_model_for(
    const GlintDesc& desc, const std::shared_ptr<const EnvironmentMap>& env) {
    return model_for(desc, env);
}

int wang2020_glint_blur_taps(const Scene& scene, bool one_sample) {
    const MaterialDesc* owner = nullptr;
    int taps = 1;
    for (const Shape& shape : scene.shapes) {
        if (shape.material < 0 || static_cast<size_t>(shape.material) >= scene.materials.size())
            continue;
        const MaterialDesc& m = scene.materials[static_cast<size_t>(shape.material)];
        if (m.type != MaterialDesc::Type::Glint) continue;
        const auto* p = std::get_if<Wang2020Params>(&m.glint.params);
        if (p == nullptr || !p->blur) continue;
        using B = Wang2020Params::GlintBlur;
        const int own =
            p->glint_blur == B::AsPublished || (p->glint_blur == B::Auto && one_sample) ? 3 : 1;
        if (owner != nullptr && own != taps)
            fail(
                "wang2020: materials \"{}\" and \"{}\" differ in \"glint_blur\" ({} and {} "
                "taps here): one 001 §4.4 post-process runs per image, so every wang2020 "
                "material with \"blur\" on must resolve to the same kernel",
                owner->name, m.name, taps, own);
        owner = &m;
        taps = own;
    }
    return taps;
}

bool wang2020_shades_light(const GlintDesc&, const Scene& scene, int light) {
    const Light& l = scene.lights[static_cast<size_t>(light)];
    return std::holds_alternative<EnvironmentLight>(l) || std::holds_alternative<PointLight>(l) ||
           std::holds_alternative<DirectionalLight>(l);
}

glm::vec3 wang2020_light_radiance(const GlintLightingContext& ctx, int light) {
    const Light& l = ctx.scene->lights[static_cast<size_t>(light)];
    const GlintDesc& desc = *ctx.desc;
    if (ctx.wo.z <= 0.0f) return glm::vec3(0.0f);
    const UvBox A = box_of(ctx.footprint);
    const glm::dvec3 wo(ctx.wo);
    const glm::dvec3 tint(desc.color);
    if (const auto* e = std::get_if<EnvironmentLight>(&l)) {
        const auto model = model_for(desc, e->map);
        const Wang2020Params& params = params_of(desc);
        // §4.4 directional occlusion: one ray along the mirror direction.
        bool visible = true;
        if (params.directional_occlusion) {
            const glm::vec3 r = ctx.to_world(glm::vec3(-ctx.wo.x, -ctx.wo.y, ctx.wo.z));
            visible = ctx.visible(r, std::numeric_limits<float>::infinity());
        }
        // With an image pass behind (renders), the glint layer and its
        // visibility go to the §4.4 blurs (δ = G9 * visibility, G3 * (rgb δ));
        // otherwise the unblurred visibility multiplies the radiance.
        const bool deferred = ctx.post != nullptr && params.blur;
        if (!visible && !deferred) return glm::vec3(0.0f);
        const glm::vec3 L = glm::vec3(
            model->environment_radiance(A, glm::dvec3(ctx.n), glm::dvec3(ctx.to_world(ctx.wo))) *
            tint);
        if (!deferred) return L;
        ctx.post->rgb += L;
        ctx.post->visibility = std::min(ctx.post->visibility, visible ? 1.0f : 0.0f);
        ctx.post->active = true;
        return glm::vec3(0.0f);
    }
    const auto model = model_for(desc, {});
    glm::vec3 wi_world;
    glm::dvec3 li;
    float t_max = std::numeric_limits<float>::infinity();
    if (const auto* pl = std::get_if<PointLight>(&l)) {
        const glm::vec3 d = pl->position - ctx.p;
        const float dist = glm::length(d);
        if (!(dist > 0.0f)) return glm::vec3(0.0f);
        wi_world = d / dist;
        li = glm::dvec3(pl->intensity) / (static_cast<double>(dist) * dist);
        t_max = dist * (1.0f - 1e-4f);
    } else if (const auto* dl = std::get_if<DirectionalLight>(&l)) {
        // A cone light is treated as a delta light along its axis (Eq. 21).
        wi_world = glm::normalize(dl->direction);
        li = glm::dvec3(dl->irradiance);
    } else {
        return glm::vec3(0.0f);
    }
    const glm::dvec3 wi(ctx.to_local(wi_world));
    if (wi.z <= 0.0 || !ctx.visible(wi_world, t_max)) return glm::vec3(0.0f);
    return glm::vec3(model->light_radiance(A, wi, wo, li) * tint);  // Eq. 21
}

}  // namespace glintlab
