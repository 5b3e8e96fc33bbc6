#include "glintlab/compare/compare.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/glints/facet_extent.h"
#include "glintlab/glints/registry.h"
#include "glintlab/loader/scene_edits.h"
#include "glintlab/render/accel.h"
#include "glintlab/render/renderer.h"
#if GLINTLAB_WITH_GL
#include "glintlab/gl/gl_context.h"
#include "glintlab/realtime/glint_programs.h"
#include "glintlab/realtime/gpu_renderer.h"
#endif

namespace glintlab::compare {
namespace {

GlintLightType light_type(const Light& light) {
    return std::visit(
        [](const auto& l) {
            using T = std::decay_t<decltype(l)>;
            if constexpr (std::is_same_v<T, PointLight>) return GlintLightType::Point;
            if constexpr (std::is_same_v<T, DirectionalLight>) return GlintLightType::Directional;
            if constexpr (std::is_same_v<T, SphereLight>) return GlintLightType::Sphere;
            return GlintLightType::Environment;
        },
        light);
}

// The sampling seed offset of the resampled frame (sampling_flicker): far
// from every realization's seed + r (r < 4096).
constexpr uint64_t kResampleSeedOffset = 0x9e3779b9u;

// The camera of frame t of the flicker path: the eye orbits the target about
// the camera's up axis, orbit_deg over the whole path (Rodrigues' rotation).
Camera path_camera(const Camera& camera, int t, int frames, double orbit_deg) {
    Camera c = camera;
    if (t == 0 || frames < 2) return c;
    const double angle = orbit_deg * 3.14159265358979323846 / 180.0 * double(t) / (frames - 1);
    const glm::dvec3 k = glm::normalize(glm::dvec3(camera.up));
    const glm::dvec3 v = glm::dvec3(camera.eye - camera.target);
    const glm::dvec3 r = v * std::cos(angle) + glm::cross(k, v) * std::sin(angle) +
                         k * glm::dot(k, v) * (1.0 - std::cos(angle));
    c.eye = camera.target + glm::vec3(r);
    return c;
}

// The pixels whose centre ray first hits a shape of material `material`.
// The pixels the material covers entirely: the rays through the pixel's
// centre and (just inside) its four corners all hit it. A silhouette pixel
// mixes the material with what lies behind it in proportions that depend on
// where the samples fall: the CPU jitters --spp samples over the pixel, the
// GPU shades its centre once, so with the silhouette in the mask a model
// rendered with --gpu measured 2-6 % brighter than the same model on the
// CPU at 64x64 and 4 spp (5 % at 32x32): an antialiasing difference, not
// a model's. Inside the material, both estimate the same pixel mean.
Mask material_mask(const Scene& scene, const Accelerator& accel, const Camera& camera,
                   int material) {
    static constexpr glm::vec2 kPoints[5] = {
        {0.5f, 0.5f}, {0.001f, 0.001f}, {0.999f, 0.001f}, {0.001f, 0.999f}, {0.999f, 0.999f}};
    Mask mask(size_t(camera.width) * size_t(camera.height), 0);
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            bool covered = true;
            for (const glm::vec2& p : kPoints) {
                const Ray ray = camera.generate(glm::vec2(float(x), float(y)) + p).ray;
                const std::optional<SurfaceHit> hit =
                    accel.intersect(ray, std::numeric_limits<float>::infinity());
                if (!hit || hit->shape < 0 ||
                    scene.shapes[size_t(hit->shape)].material != material) {
                    covered = false;
                    break;
                }
            }
            mask[size_t(y) * camera.width + x] = covered ? 1 : 0;
        }
    return mask;
}

std::string truth_key(const GlintDesc& d) {
    std::string maps;
    if (const GlintTextures* t = d.textures.get()) {
        auto add = [&](bool on, const char* name) {
            if (on) maps += fmt::format("{}{}", maps.empty() ? ", maps: " : " ", name);
        };
        add(t->density != nullptr, "density");
        add(t->alpha_x_sq || t->alpha_y_sq, "roughness");
        add(t->color != nullptr, "color");
        add(t->base_albedo != nullptr, "base");
    }
    return fmt::format("explicit {} alpha {:.4g}x{:.4g} ln density {:.4g} gamma {:.3g} deg{}",
                       d.ndf == NdfType::GGX ? "ggx" : "beckmann", d.alpha_x, d.alpha_y,
                       d.log_density, std::get<ExplicitParams>(d.params).gamma_deg, maps);
}

// One set of renders: a model (or the truth) on R realizations, and P
// camera paths of F frames (path p: realization p's seeds).
struct Job {
    size_t row = 0;  // index into result.models
    GlintDesc desc;
    bool gpu = false;
    std::vector<Plane> realizations;
    std::vector<std::vector<Plane>> paths;
    std::vector<double> means;
};

double ratio(double a, double b) {
    if (b > 0.0) return a / b;
    return a == 0.0 ? 1.0 : std::numeric_limits<double>::infinity();
}

void check_options(const CompareOptions& o) {
    const std::string scene = o.scene.string();
    if (o.realizations < 2 || o.realizations > 256)
        fail("compare {}: --realizations must be in [2, 256] (a variance needs two), got {}", scene,
             o.realizations);
    if (o.truth_realizations != 0 && (o.truth_realizations < 2 || o.truth_realizations > 4096))
        fail(
            "compare {}: --truth-realizations must be 0 (as --realizations) or in [2, 4096], got "
            "{}",
            scene, o.truth_realizations);
    if (o.frames < 2 || o.frames > 256)
        fail("compare {}: --frames must be in [2, 256], got {}", scene, o.frames);
    if (o.flicker_paths < 1 || o.flicker_paths > 256)
        fail("compare {}: --flicker-paths must be in [1, 256], got {}", scene, o.flicker_paths);
    if ((o.width != 0 || o.height != 0) &&
        (o.width < 1 || o.height < 1 || o.width > 16384 || o.height > 16384))
        fail("compare {}: --res: W and H must be in [1, 16384], got {}x{}", scene, o.width,
             o.height);
    if (o.spp < 0 || o.spp > (1 << 20))
        fail("compare {}: --spp must be in [1, 1048576], got {}", scene, o.spp);
    if (!(std::isfinite(o.orbit_deg) && o.orbit_deg > 0.0 && o.orbit_deg <= 90.0))
        fail("compare {}: --orbit must be in (0, 90] degrees, got {}", scene, o.orbit_deg);
    if (o.threads < 0 || o.threads > 1024)
        fail("compare {}: --threads must be in [0, 1024], got {}", scene, o.threads);
}

}  // namespace

const ModelMetrics* CompareResult::find(const std::string& model) const {
    for (const ModelMetrics& m : models)
        if (m.model == model) return &m;
    return nullptr;
}

CompareResult run_compare(const CompareOptions& o) {
    check_options(o);
    const std::string scene_name = o.scene.string();
    Scene base = load_scene(o.scene, SceneEdits{"", o.sets});
    if (o.width > 0) base.camera.width = o.width, base.camera.height = o.height;
    if (o.spp > 0) base.render.spp = o.spp;

    // The compared material.
    int mi = -1;
    std::string glint_names;
    for (size_t i = 0; i < base.materials.size(); ++i) {
        const MaterialDesc& m = base.materials[i];
        if (m.type != MaterialDesc::Type::Glint) continue;
        glint_names += (glint_names.empty() ? "" : ", ") + m.name;
        if (mi < 0 && (o.material.empty() || m.name == o.material)) mi = int(i);
    }
    if (glint_names.empty())
        fail("compare {}: the scene has no glint material (\"type\": \"glint\") to compare",
             scene_name);
    if (mi < 0)
        fail("compare {}: --material {}: no glint material of that name (glint materials: {})",
             scene_name, o.material, glint_names);
    const GlintDesc original = base.materials[size_t(mi)].glint;

    // The models asked for.
    std::vector<const GlintModelDescriptor*> asked;
    const bool all = o.models.empty() || (o.models.size() == 1 && o.models[0] == "all");
    for (const GlintModelDescriptor& m : glint_models())
        if (all || std::find(o.models.begin(), o.models.end(), m.name) != o.models.end())
            asked.push_back(&m);
    if (!all)
        for (const std::string& name : o.models)
            if (find_glint_model(name) == nullptr)
                fail("compare {}: --models: unknown model \"{}\" (known: {}, or all)", scene_name,
                     name, glint_model_names());

    CompareResult result;
    result.scene = scene_name;
    result.material = base.materials[size_t(mi)].name;
    std::vector<GlintLightType> types;
    for (const Light& l : base.lights) {
        const GlintLightType t = light_type(l);
        if (std::find(types.begin(), types.end(), t) == types.end()) types.push_back(t);
    }
    for (GlintLightType t : types)
        result.lights +=
            (result.lights.empty() ? "" : ", ") + std::string(glint_light_type_name(t));
    result.width = base.camera.width, result.height = base.camera.height;
    result.spp = base.render.spp;
    result.realizations = o.realizations, result.frames = o.frames;
    result.flicker_paths = o.flicker_paths;
    result.truth_realizations = o.truth_realizations > 0 ? o.truth_realizations : o.realizations;
    result.orbit_deg = o.orbit_deg;
    result.blur_sigma_px = sparkle_blur_sigma(result.width, result.height);

#if GLINTLAB_WITH_GL
    const bool gl = true;
#else
    const bool gl = false;
    if (o.gpu) fail("compare --gpu: this glintlab was built without OpenGL (GLINTLAB_WITH_GL=OFF)");
#endif

    // One job per model that can shade the scene's lights, and one ground
    // truth per distinct material they were fitted to (a model's
    // fit_material may change the NDF, roughness or density: each is compared
    // with explicit microfacets of the same distribution).
    std::vector<Job> jobs;
    std::map<std::string, size_t> truth_job;  // key -> index into jobs
    // The truth's reflection cone under delta lights (explicit's gamma_deg:
    // the scene's when the scene's material is explicit, else its default).
    double truth_gamma_deg = ExplicitParams{}.gamma_deg;
    if (original.model_id == GlintModelId::Explicit)
        truth_gamma_deg = std::get<ExplicitParams>(original.params).gamma_deg;
    const double truth_gamma = glm::radians(truth_gamma_deg);
    auto add_truth = [&](const GlintDesc& fitted, double gamma_deg) {
        GlintDesc t = original;
        switch_glint_model(t, GlintModelId::Explicit);
        if (original.model_id == GlintModelId::Explicit) t.params = original.params;
        std::get<ExplicitParams>(t.params).gamma_deg = float(gamma_deg);
        // Silhouette samples (outside the mask) have footprints of
        // unbounded area: a part of them, unbiased, rather than an error.
        std::get<ExplicitParams>(t.params).subsample_over_budget = true;
        t.ndf = fitted.ndf, t.alpha_x = fitted.alpha_x, t.alpha_y = fitted.alpha_y;
        t.log_density = std::clamp(fitted.log_density, 0.0f, 30.0f);  // explicit's range
        t.base_albedo = glm::vec3(0.0f);
        // The truth reads the textures the model reads (a model that cannot
        // read one got its map's mean: switch_glint_model), not the base.
        if (fitted.textures) {
            GlintTextures maps = *fitted.textures;
            maps.base_albedo = nullptr;
            t.textures = std::make_shared<const GlintTextures>(std::move(maps));
        } else {
            t.textures = nullptr;
        }
        const std::string key = truth_key(t);
        const auto it = truth_job.find(key);
        if (it != truth_job.end()) return std::pair{it->second, key};
        ModelMetrics row;
        row.model = "explicit", row.compared = true, row.reference = true, row.backend = "cpu";
        row.truth = key;
        row.facet_extent = fmt::format("gamma_deg {:.3g}", gamma_deg);
        result.models.push_back(row);
        Job j;
        j.row = result.models.size() - 1, j.desc = t;
        jobs.push_back(std::move(j));
        truth_job[key] = jobs.size() - 1;
        return std::pair{jobs.size() - 1, key};
    };
    // The scene's own material first: its truth is the first row.
    {
        GlintDesc d = original;
        if (d.model_id != GlintModelId::Explicit && find_glint_model(d.model_id)->fit_material)
            find_glint_model(d.model_id)->fit_material(d);
        add_truth(d, truth_gamma_deg);
    }
    std::vector<std::pair<size_t, size_t>> pairs;  // (model job, truth job)
    for (const GlintModelDescriptor* m : asked) {
        if (m->id == GlintModelId::Explicit) continue;  // the truth rows
        ModelMetrics row;
        row.model = std::string(m->name);
        std::string missing;
        for (GlintLightType t : types)
            if (!m->shades(t))
                missing += (missing.empty() ? "" : ", ") + std::string(glint_light_type_name(t));
        if (!missing.empty()) {
            std::string shades;
            for (GlintLightType t : m->lights)
                shades += (shades.empty() ? "" : ", ") + std::string(glint_light_type_name(t));
            row.reason = fmt::format("cannot shade {} lights (it shades {})", missing, shades);
            result.models.push_back(row);
            continue;
        }
        bool on_gpu = false;
#if GLINTLAB_WITH_GL
        on_gpu = o.gpu && m->gpu && gl::gpu_supports_model(m->id);
#endif
        if (!m->cpu && !on_gpu) {
            row.reason = gl ? "GPU only: use --gpu" : "GPU only, and this build has no OpenGL";
            result.models.push_back(row);
            continue;
        }
        GlintDesc d = original;
        switch_glint_model(d, m->id);
        // The scene's own model keeps the scene's parameters (a researcher's
        // tuned material); the others get their defaults, with the facets'
        // angular extent matched to the truth's (facet_extent.h): the
        // variance and flicker of the sparkles follow it, e.g. deliot2023's
        // default microfacet_roughness makes facets 29x wider than explicit's
        // 1-degree cone at roughness 0.3 (docs/VALIDATION.md "compare").
        // A model whose method fixes the extent gets a truth of its extent.
        double gamma_deg = truth_gamma_deg;
        const bool lost_maps =
            original.textures &&
            ((original.textures->density && !(d.textures && d.textures->density)) ||
             (original.textures->alpha_x_sq && !(d.textures && d.textures->alpha_x_sq)));
        if (m->id == original.model_id) {
            d.params = original.params;
            row.facet_extent = "the scene's parameters";
        } else if (o.match_facet_extent && m->match_facet_cone) {
            row.facet_extent = m->match_facet_cone(d, truth_gamma);
        } else {
            row.facet_extent =
                m->match_facet_cone || m->facet_cone ? "the model's defaults" : "none (no facets)";
        }
        if (o.match_facet_extent && m->facet_cone) {
            // The truth's cone, clamped to explicit's gamma_deg range.
            GlintDesc cone;
            switch_glint_model(cone, GlintModelId::Explicit);
            row.facet_extent = "fixed by the method: the truth's " +
                               set_facet_cone_param(cone, "gamma_deg", m->facet_cone(d));
            gamma_deg = std::get<ExplicitParams>(cone.params).gamma_deg;
        }
        d.base_albedo = glm::vec3(0.0f);  // the truth has no diffuse base either
        if (d.textures && d.textures->base_albedo) {
            GlintTextures maps = *d.textures;
            maps.base_albedo = nullptr;
            d.textures = std::make_shared<const GlintTextures>(std::move(maps));
        }
        if (lost_maps)
            row.facet_extent +=
                "; density/roughness maps replaced by their means (the model "
                "cannot read them), against a truth of the same means";
        const auto [truth, key] = add_truth(d, gamma_deg);
        row.compared = true;
        row.backend = on_gpu ? "gpu" : "cpu";
        row.truth = key;
        result.models.push_back(row);
        Job j;
        j.row = result.models.size() - 1, j.desc = d, j.gpu = on_gpu;
        jobs.push_back(std::move(j));
        pairs.emplace_back(jobs.size() - 1, truth);
    }

    // Cameras and masks of the path.
    const Accelerator accel(base);
    std::vector<Camera> cameras;
    std::vector<Mask> masks;
    for (int t = 0; t < o.frames; ++t) {
        cameras.push_back(path_camera(base.camera, t, o.frames, o.orbit_deg));
        masks.push_back(material_mask(base, accel, cameras.back(), mi));
    }
    result.mask = masks[0];
    result.mask_pixels = std::count(masks[0].begin(), masks[0].end(), uint8_t(1));
    if (result.mask_pixels == 0)
        fail(
            "compare {}: material \"{}\" covers no pixel of the camera's view entirely (at "
            "{}x{}; a larger --res may help)",
            scene_name, result.material, result.width, result.height);

#if GLINTLAB_WITH_GL
    std::unique_ptr<HeadlessContext> context;
    std::unique_ptr<GpuRenderer> gpu;
#endif
    const int truth_realizations = o.truth_realizations > 0 ? o.truth_realizations : o.realizations;
    const auto realizations_of = [&](const Job& job) {
        return result.models[job.row].reference ? truth_realizations : o.realizations;
    };
    // The renders of a job, grouped by realization (one material seed after
    // another, so that a model's per-seed state — wang2020's particle
    // quadtree, in a cache that keeps only the most recent seeds — is built
    // once per seed):
    // realization 0 at frame 0, then frame 0 with another sampling seed
    // (the same material seed), then its path's frames 1..F-1; realization
    // r < R at frame 0 and, where r is a flicker path, frames 1..F-1; paths
    // p >= R with all their frames. Every render depends only on its
    // (realization, frame, resample), so the order changes no result.
    struct Render {
        int realization = 0, frame = 0;
        bool resample = false;
    };
    const auto renders_of = [&](const Job& job) {
        const int R = realizations_of(job);
        std::vector<Render> list;
        for (int r = 0; r < std::max(R, o.flicker_paths); ++r) {
            if (r < R) list.push_back({r, 0, false});
            if (r == 0) list.push_back({0, 0, true});
            if (r < o.flicker_paths)
                for (int t = r < R ? 1 : 0; t < o.frames; ++t) list.push_back({r, t, false});
        }
        return list;
    };
    int total = 0;
    for (const Job& job : jobs) total += int(renders_of(job).size());
    int done = 0;
    for (Job& job : jobs) {
        ModelMetrics& row = result.models[job.row];
        const int R = realizations_of(job);
        double seconds = 0.0;
        Plane resampled;  // frame 0 of realization 0, another sampling seed
        job.paths.assign(size_t(o.flicker_paths), {});
        for (const Render& render : renders_of(job)) {
            const bool resample = render.resample;
            const int r = render.realization;
            const int t = render.frame;
            Scene s = base;
            s.camera = cameras[size_t(t)];
            s.render.seed = o.seed + uint64_t(r) + (resample ? kResampleSeedOffset : 0u);
            s.materials[size_t(mi)].glint = job.desc;
            s.materials[size_t(mi)].glint.seed =
                uint32_t(original.seed + uint32_t(o.seed) + uint32_t(r));
            const auto start = std::chrono::steady_clock::now();
            Image image;
            if (job.gpu) {
#if GLINTLAB_WITH_GL
                if (!context) {
                    context = std::make_unique<HeadlessContext>();
                    gpu = std::make_unique<GpuRenderer>(s);
                }
                gpu->render(s);
                image = gpu->read_image();
                row.cut_fragments += gpu->cut_fragments();
#endif
            } else {
                image = render_scene(s, accel, RenderOptions{o.threads, true});
            }
            const double dt =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            row.faults += count_pixel_faults(image);
            Plane plane = luminance_plane(image);
            if (resample) {
                resampled = std::move(plane);
            } else if (t == 0 && r < R) {
                seconds += dt;
                job.means.push_back(masked_mean(plane, masks[0]));
                if (r == 0) row.image = std::move(image);
                if (r < o.flicker_paths) job.paths[size_t(r)].push_back(plane);
                job.realizations.push_back(std::move(plane));
            } else {
                job.paths[size_t(r)].push_back(std::move(plane));
            }
            ++done;
            if (o.progress) o.progress(done, total);
        }
        row.seconds = seconds / R;
        row.mean_plane = average(job.realizations);
        const MeanEstimate mean = mean_with_standard_error(job.means);
        row.mean_luminance = mean.mean;
        if (row.mean_luminance > 0.0)
            row.mean_luminance_rel_se = mean.standard_error / row.mean_luminance;
        row.pixel_variance = mean_pixel_variance(job.realizations, masks[0]);
        const FlickerEstimate f = flicker_over_paths(job.paths, masks);
        row.flicker = f.mean, row.flicker_se = f.standard_error;
        row.sampling_flicker = flicker({job.realizations[0], resampled}, {masks[0], masks[0]});
        row.sampling_variance = sampling_pixel_variance(job.realizations[0], resampled, masks[0]);
    }

    // Metrics against each model's truth.
    for (const Job& truth : jobs) {
        if (!result.models[truth.row].reference) continue;
        ModelMetrics& row = result.models[truth.row];
        row.variance_ratio = 1.0, row.flicker_ratio = 1.0, row.structure_variance_ratio = 1.0;
    }
    for (const auto& [mj, tj] : pairs) {
        const Job &model = jobs[mj], &truth = jobs[tj];
        ModelMetrics& row = result.models[model.row];
        const ModelMetrics& t = result.models[truth.row];
        const MeanError e = mean_relative_error(model.means, truth.means);
        row.mean_rel_err = e.relative_error, row.mean_rel_err_se = e.standard_error;
        row.blurred_rel_rmse =
            blurred_relative_rmse(row.mean_plane, t.mean_plane, masks[0], result.blur_sigma_px);
        row.variance_ratio = ratio(row.pixel_variance, t.pixel_variance);
        row.structure_variance_ratio =
            ratio(std::max(row.pixel_variance - row.sampling_variance, 0.0),
                  std::max(t.pixel_variance - t.sampling_variance, 0.0));
        // A distance relative to the truth's mean: 0 when the pooled values
        // agree, black images included (ratio's 0/0 = 1 is for variances).
        const double w = wasserstein1(pooled_masked_values(model.realizations, masks[0]),
                                      pooled_masked_values(truth.realizations, masks[0]));
        row.wasserstein = w == 0.0 ? 0.0 : ratio(w, t.mean_luminance);
        row.flicker_ratio = ratio(row.flicker, t.flicker);
        if (row.flicker > 0.0 && t.flicker > 0.0)
            row.flicker_ratio_se = row.flicker_ratio * std::hypot(row.flicker_se / row.flicker,
                                                                  t.flicker_se / t.flicker);
    }
    return result;
}

}  // namespace glintlab::compare
