#include "glintlab/validate/robustness_suite.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <mutex>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/parallel_for.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/glint_bxdf.h"
#include "glintlab/glints/glint_lighting.h"
#include "glintlab/glints/registry.h"
#include "glintlab/glints/wang2020/wang2020_quadtree.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/scene/scene.h"
#include "glintlab/validate/random_queries.h"

namespace glintlab {
namespace {

// "key=value ..." of a model's parameter block, from its descriptor's table.
std::string model_params_text(const GlintModelDescriptor& model, const GlintModelParams& params) {
    std::string text;
    for (const GlintParam& p : model.params)
        text += (text.empty() ? "" : " ") + p.key + "=" + glint_param_value_text(p.get(params));
    return text;
}

constexpr double kPi = 3.14159265358979323846;

// How one model is swept. Parameter blocks are JSON as a scene writes them
// (read by the scene loader, so each is range-checked like a user's); the
// listed ones are each block's extremes.
struct ModelSweep {
    std::string model;
    std::vector<nlohmann::json> blocks;
    std::vector<std::string> ndfs;  // "beckmann", "ggx"
    double roughness_lo = 1e-3, roughness_hi = 1.0;
    bool isotropic = false;
    double log_density_lo = -20.0, log_density_hi = 60.0;
    // Whether roughness and log density may change per evaluation. Models
    // that build tables from them (wang2020) keep each material's values
    // and sweep a few materials at the range ends instead.
    bool per_evaluation_material = true;
    // Largest footprint side in uv (log10): models that enumerate facets or
    // particles refuse footprints holding more than their budget.
    double footprint_hi_exp10 = 6.0;
    double weight = 1.0;  // share of the evaluations
};

ModelSweep sweep(std::string model, std::vector<const char*> blocks,
                 std::vector<std::string> ndfs) {
    ModelSweep m;
    m.model = std::move(model);
    for (const char* b : blocks) m.blocks.push_back(nlohmann::json::parse(b));
    m.ndfs = std::move(ndfs);
    return m;
}

std::vector<ModelSweep> sweeps() {
    std::vector<ModelSweep> s;
    s.push_back(sweep("smooth", {"{}"}, {"beckmann", "ggx"}));
    s.push_back(sweep("deliot2023",
                      {"{}",
                       R"({"microfacet_roughness": 1e-4, "screen_space_scale": 0.5,
                           "density_randomization": 50})",
                       R"({"microfacet_roughness": 1, "screen_space_scale": 8,
                           "density_randomization": 0, "original_defects": true})"},
                      {"beckmann", "ggx"}));
    s.push_back(sweep(
        "zirr2016",
        {"{}", R"({"microfacet_roughness": 1e-4, "max_anisotropy": 1, "screen_space_scale": 0.5})",
         R"({"microfacet_roughness": 1, "max_anisotropy": 64, "screen_space_scale": 8})"},
        {"beckmann", "ggx"}));
    s.push_back(
        sweep("chermain2020",
              {"{}", R"({"relative_area": 0, "max_anisotropy": 1, "density_randomization": 8})",
               R"({"relative_area": 1, "max_anisotropy": 32, "density_randomization": 0,
                           "colours": [[0, 0, 0], [1, 1, 1], [1, 0, 0.5]]})"},
              {"beckmann"}));
    {
        ModelSweep k = sweep(
            "kneiphof2025",
            {"{}",
             R"({"levels": 4, "black_level": 1e-8, "density_randomization": 50,
                 "microfacet_roughness": 1e-4, "screen_space_scale": 0.5,
                 "gaussian": "algorithm1", "smooth": "lobe"})",
             R"({"levels": 8, "black_level": 1, "density_randomization": 20,
                 "microfacet_roughness": 1, "screen_space_scale": 8})",
             R"({"variant": "wang2020_style", "gamma_deg": 0.01, "density_randomization": 50})",
             R"({"variant": "wang2020_style", "gamma_deg": 45, "gaussian": "algorithm1"})"},
            {"ggx"});
        k.isotropic = true;
        s.push_back(k);
    }
    {
        ModelSweep j = sweep(
            "jakob2014",
            {"{}", R"({"gamma_deg": 0.5, "error_threshold": 0, "max_depth": 8, "chromatic": true})",
             R"({"gamma_deg": 6, "error_threshold": 0.5, "max_depth": 28, "query_area": 1e-16})"},
            {"beckmann", "ggx"});
        j.log_density_hi = 36.7;  // N = e^log_density <= 2^53 (read_jakob2014_params)
        j.footprint_hi_exp10 = -3.0;
        j.weight = 0.002;  // a tree traversal per query, ~10-50 ms
        s.push_back(j);
    }
    {
        ModelSweep e = sweep("explicit",
                             {"{}", R"({"gamma_deg": 0.5, "max_facets_per_footprint": 1})",
                              R"({"gamma_deg": 6, "max_facets_per_footprint": 1e5})"},
                             {"beckmann", "ggx"});
        e.log_density_lo = 0.0, e.log_density_hi = 30.0;  // read_explicit_params
        e.footprint_hi_exp10 = -3.0;
        e.weight = 0.05;  // facets enumerated one by one
        s.push_back(e);
    }
    {
        // Tables per (roughness, log density, parameters): materials at the
        // range ends, with small tables so that they build in seconds. The
        // quadtree depth is within the range allowed at the material's
        // density (wang2020_quadtree.h: at most 4096 particles per leaf, at
        // most 1.25e8 nodes): the shallowest for roughness 0.02 (1 at ln N 0,
        // 8 at 19.4: the most particles per leaf); for roughness 1 the
        // deepest, 16, at ln N 0 and the paper's 11 at 19.4 (the deepest
        // allowed there, 13, is a tree of 8.9e7 nodes: tens of seconds and
        // 3 GB to build).
        ModelSweep w = sweep("wang2020", {}, {"beckmann"});
        for (double a : {0.02, 1.0})
            for (double ld : {0.0, 19.4}) {
                const auto n =
                    static_cast<uint64_t>(std::llround(std::exp(double(static_cast<float>(ld)))));
                const int depth =
                    a < 0.5 ? wang2020::min_quadtree_depth(n)
                            : std::min(wang2020::max_quadtree_depth(n), ld > 0.0 ? 11 : 16);
                nlohmann::json params = {{"gamma_deg", a < 0.5 ? 1.0 : 30.0},
                                         {"depth", depth},
                                         {"dpf_theta", 8},
                                         {"dpf_phi", 16},
                                         {"prefilter_samples", 1}};
                nlohmann::json b = nlohmann::json::object();
                b["roughness"] = a;
                b["log_density"] = ld;
                b["params"] = params;
                w.blocks.push_back(b);
            }
        w.isotropic = true;
        w.per_evaluation_material = false;
        w.log_density_lo = 0.0, w.log_density_hi = 19.4;  // read_wang2020_params
        w.footprint_hi_exp10 = 0.0;
        w.weight = 0.1;
        s.push_back(w);
    }
    return s;
}

// The scene of one model: one sphere per material (block × NDF), every light
// type the model supports: a constant environment of radiance 10^6 (the
// brightest a scene allows is 10^15; 10^6 already overflows L · N in fp32
// at N = e^80), a sun cone, a sphere light and a point light.
Scene scene_for(const ModelSweep& m, const GlintModelInfo& info) {
    using nlohmann::json;
    json materials = json::array(), shapes = json::array(), lights = json::array();
    int i = 0;
    for (const json& variant : m.blocks) {
        const bool wrapped = variant.contains("params");
        for (const std::string& ndf : m.ndfs) {
            json mat = {{"name", fmt::format("m{}", i)},
                        {"type", "glint"},
                        {"model", m.model},
                        {"ndf", ndf},
                        {"roughness", wrapped ? variant.at("roughness") : json(0.3)},
                        {"log_density", wrapped ? variant.at("log_density") : json(20.0)},
                        {"seed", i + 1}};
            if (m.model != "smooth") mat[m.model] = wrapped ? variant.at("params") : variant;
            materials.push_back(mat);
            shapes.push_back({{"type", "sphere"},
                              {"radius", 0.1},
                              {"center", {3.0 * i, 0.0, 0.0}},
                              {"material", fmt::format("m{}", i)}});
            ++i;
        }
    }
    if (info.shades(GlintLightType::Environment))
        lights.push_back({{"type", "environment"}, {"radiance", {1e6, 1e6, 1e6}}});
    if (info.shades(GlintLightType::Directional))
        lights.push_back({{"type", "directional"},
                          {"direction", {0.3, 1.0, 0.2}},
                          {"irradiance", {1e3, 1e3, 1e3}},
                          {"solid_angle_sr", 6.8e-5}});
    if (info.shades(GlintLightType::Sphere))
        lights.push_back({{"type", "sphere"},
                          {"center", {0.0, 5.0, 0.0}},
                          {"radius", 0.5},
                          {"radiance", {10.0, 10.0, 10.0}}});
    if (info.shades(GlintLightType::Point))
        lights.push_back({{"type", "point"},
                          {"position", {0.0, 5.0, 5.0}},
                          {"intensity", {100.0, 100.0, 100.0}}});
    const json doc = {{"film", {{"width", 8}, {"height", 8}}},
                      {"camera", {{"eye", {0, 0, 5}}, {"target", {0, 0, 0}}, {"fov_deg", 45}}},
                      {"render", {{"integrator", "direct"}, {"spp", 1}}},
                      {"materials", materials},
                      {"shapes", shapes},
                      {"lights", lights}};
    return parse_scene(doc, fmt::format("<robustness suite: {}>", m.model));
}

// cos θ of a direction: normal, grazing (down to 1e-7) or uniform; the
// azimuth is uniform.
glm::vec3 draw_direction(Pcg32& rng, bool allow_below) {
    double z;
    switch (rng.next_uint(8)) {
        case 0:
            z = 1.0;
            break;
        case 1:
            z = pow10_uniform(rng, -7, -1);
            break;
        case 2:
            z = allow_below ? -pow10_uniform(rng, -7, 0) : rng.next_double();
            break;
        default:
            z = rng.next_double();
    }
    const double phi = 2.0 * kPi * rng.next_double(), r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return glm::normalize(glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
}

// A footprint: zero, degenerate (collinear or one axis zero), or oriented
// with minor width 10^[-20, hi] and anisotropy up to 10^8.
Footprint draw_footprint(Pcg32& rng, double hi_exp10) {
    const glm::vec2 uv(float(rng.next_double() * 4.0 - 2.0), float(rng.next_double() * 4.0 - 2.0));
    Footprint fp = oriented_footprint(uv, pow10_uniform(rng, -20, hi_exp10),
                                      rng.next_uint(2) == 0 ? 1.0 : pow10_uniform(rng, 0, 8),
                                      rng.next_double() * 2.0 * kPi);
    const double major = glm::length(fp.duvdx);
    if (major > std::pow(10.0, hi_exp10)) fp.duvdx *= float(std::pow(10.0, hi_exp10) / major);
    switch (rng.next_uint(12)) {
        case 0:
            fp.duvdx = fp.duvdy = glm::vec2(0.0f);
            break;
        case 1:
            fp.duvdy = fp.duvdx * (rng.next_float() - 0.5f);
            break;
        case 2:
            fp.duvdy = glm::vec2(0.0f);
            break;
        default:
            break;
    }
    return fp;
}

double draw_log_density(Pcg32& rng, const ModelSweep& m) {
    switch (rng.next_uint(8)) {
        case 0:
            return m.log_density_lo;
        case 1:
            return m.log_density_hi;
        default:
            return m.log_density_lo + (m.log_density_hi - m.log_density_lo) * rng.next_double();
    }
}

double draw_roughness(Pcg32& rng, const ModelSweep& m) {
    switch (rng.next_uint(8)) {
        case 0:
            return m.roughness_lo;
        case 1:
            return m.roughness_hi;
        default:
            return m.roughness_lo * std::pow(m.roughness_hi / m.roughness_lo, rng.next_double());
    }
}

bool bad(glm::vec3 v) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(v[c]) || v[c] < 0.0f) return true;
    return false;
}

RobustnessModelResult sweep_model(const ModelSweep& m, int64_t evaluations, uint64_t seed) {
    const GlintModelInfo* info = find_glint_model(m.model);
    if (!info) fail("robustness suite: unknown model {}", m.model);
    const Scene scene = scene_for(m, *info);
    RobustnessModelResult result;
    result.model = m.model;
    std::atomic<int64_t> n_evals{0}, n_bad{0}, n_refused{0};
    std::mutex first_mutex;
    constexpr int64_t kChunk = 4096;
    const int64_t chunks = (evaluations + kChunk - 1) / kChunk;
    tbb::parallel_for(int64_t{0}, chunks, [&](int64_t c) {
        Pcg32 rng(mix_bits(static_cast<uint64_t>(c) + 1),
                  mix_bits(seed ^ std::hash<std::string>{}(m.model)));
        std::vector<GlintDesc> descs;
        for (const MaterialDesc& md : scene.materials) descs.push_back(md.glint);
        int64_t local_evals = 0, local_bad = 0, local_refused = 0;
        const int64_t target = std::min(kChunk, evaluations - c * kChunk);
        while (local_evals < target) {
            const size_t mi = rng.next_uint(uint32_t(descs.size()));
            GlintDesc& desc = descs[mi];
            if (m.per_evaluation_material) {
                desc.log_density = float(draw_log_density(rng, m));
                desc.alpha_x = float(draw_roughness(rng, m));
                desc.alpha_y = m.isotropic ? desc.alpha_x : float(draw_roughness(rng, m));
                desc.seed = rng.next_uint();
            }
            const glm::vec3 wo = draw_direction(rng, false);
            glm::vec3 wi = draw_direction(rng, true);
            if (rng.next_uint(2) == 0) {
                // Near the mirror direction: where D_P's peaks are.
                const glm::vec3 h = draw_direction(rng, false);
                wi = 2.0f * glm::dot(wo, h) * h - wo;
            }
            const Footprint fp = draw_footprint(rng, m.footprint_hi_exp10);
            const GlintBxdf bxdf{&desc, true, fp};
            const glm::vec3 hv = wo + wi;
            const glm::vec3 h = glm::length(hv) > 0.0f ? glm::normalize(hv) : glm::vec3(0, 0, 1);
            auto record = [&](glm::vec3 v, const std::string& what) {
                ++local_evals;
                if (!bad(v)) return;
                ++local_bad;
                const std::lock_guard lock(first_mutex);
                if (result.first_bad.empty())
                    result.first_bad = fmt::format(
                        "{} = ({}, {}, {}) at material {} (block {}), alpha ({}, {}), log_density "
                        "{}, wo ({}, {}, {}), wi ({}, {}, {}), footprint uv ({}, {}) duvdx ({}, "
                        "{}) duvdy ({}, {})",
                        what, v.x, v.y, v.z, mi, model_params_text(*info, desc.params),
                        desc.alpha_x, desc.alpha_y, desc.log_density, wo.x, wo.y, wo.z, wi.x, wi.y,
                        wi.z, fp.uv.x, fp.uv.y, fp.duvdx.x, fp.duvdx.y, fp.duvdy.x, fp.duvdy.y);
            };
            try {
                record(bxdf.footprint_ndf_rgb(wo, wi, h), "footprint_ndf_rgb");
                record(bxdf.f(wo, wi), "f");
                if (info->shades_light && info->light_radiance) {
                    GlintLightingContext ctx;
                    ctx.scene = &scene;
                    ctx.desc = &desc;
                    ctx.p = glm::vec3(0.0f);
                    ctx.t = glm::vec3(1, 0, 0), ctx.b = glm::vec3(0, 0, -1),
                    ctx.n = glm::vec3(0, 1, 0);
                    ctx.wo = wo;
                    ctx.footprint = fp;
                    ctx.visible = [](glm::vec3, float) { return true; };
                    ctx.rng = &rng;
                    for (int l = 0; l < int(scene.lights.size()); ++l)
                        if (info->shades_light(desc, scene, l))
                            record(info->light_radiance(ctx, l),
                                   fmt::format("light_radiance of light {}", l));
                }
            } catch (const Error& e) {
                ++local_refused;
                const std::lock_guard lock(first_mutex);
                if (result.first_refusal.empty()) result.first_refusal = e.what();
                ++local_evals;
            }
        }
        n_evals += local_evals;
        n_bad += local_bad;
        n_refused += local_refused;
    });
    result.evaluations = n_evals.load();
    result.bad_values = n_bad.load();
    result.refused = n_refused.load();
    return result;
}

}  // namespace

std::vector<RobustnessModelResult> run_robustness(const RobustnessSuiteOptions& options) {
    std::vector<ModelSweep> all = sweeps();
    double total_weight = 0.0;
    std::vector<std::string> known;
    for (const ModelSweep& m : all) {
        total_weight += m.weight;
        known.push_back(m.model);
    }
    for (const std::string& name : options.models)
        if (std::find(known.begin(), known.end(), name) == known.end())
            fail("validate robustness: unknown model \"{}\" (models: {})", name,
                 fmt::format("{}", fmt::join(known, ", ")));
    std::vector<RobustnessModelResult> results;
    for (const ModelSweep& m : all) {
        if (!options.models.empty() && std::find(options.models.begin(), options.models.end(),
                                                 m.model) == options.models.end())
            continue;
        const auto n = std::max<int64_t>(
            64, std::llround(double(options.evaluations) * m.weight / total_weight));
        const auto start = std::chrono::steady_clock::now();
        if (options.reduced && !m.per_evaluation_material) {
            ModelSweep fast = m;
            fast.blocks.clear();
            for (const nlohmann::json& b : m.blocks)
                if (b.at("log_density").get<double>() == m.log_density_lo &&
                    b.at("roughness").get<double>() == 1.0)
                    fast.blocks.push_back(b);
            results.push_back(sweep_model(fast, n, options.seed));
        } else {
            results.push_back(sweep_model(m, n, options.seed));
        }
        results.back().seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return results;
}

ValidationReport validate_robustness(const RobustnessSuiteOptions& options) {
    ValidationReport report;
    report.suite = "robustness";
    const std::vector<RobustnessModelResult> results = run_robustness(options);
    nlohmann::json models = nlohmann::json::array();
    int64_t total = 0;
    report.text = fmt::format("{:<14} {:>12} {:>10} {:>9} {:>9}\n", "model", "evaluations", "bad",
                              "refused", "seconds");
    for (const RobustnessModelResult& r : results) {
        total += r.evaluations;
        models.push_back({{"model", r.model},
                          {"evaluations", r.evaluations},
                          {"bad_values", r.bad_values},
                          {"refused", r.refused},
                          {"seconds", r.seconds},
                          {"first_bad", r.first_bad},
                          {"first_refusal", r.first_refusal}});
        report.text += fmt::format("{:<14} {:>12} {:>10} {:>9} {:>9.1f}\n", r.model, r.evaluations,
                                   r.bad_values, r.refused, r.seconds);
        if (!r.first_bad.empty()) report.text += fmt::format("  first bad: {}\n", r.first_bad);
        report.check(fmt::format("{}_bad_values", r.model), double(r.bad_values), "==", 0.0);
    }
    report.details["models"] = models;
    report.details["evaluations"] = total;
    report.details["seed"] = options.seed;
    return report;
}

ValidationReport validate_robustness(uint64_t seed) {
    RobustnessSuiteOptions o;
    o.seed = seed;
    return validate_robustness(o);
}

}  // namespace glintlab
