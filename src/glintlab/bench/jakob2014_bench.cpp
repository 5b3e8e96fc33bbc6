// jakob2014 performance (docs/BENCHMARKS.md): queries per second and nodes
// per query of D̂ (Algorithm 1) for the 002 Table 1 settings, the cost of the
// importance-sampling pdf (64-point QMC convolution), the integral-table
// build and its memory, and the render time of scenes/jakob2014_plane.json
// with jakob2014 vs the same scene with the smooth model at equal spp.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include "glintlab/core/rng.h"
#include "glintlab/glints/jakob2014/jakob2014.h"
#include "glintlab/glints/registry.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/accel.h"
#include "glintlab/render/renderer.h"
#include "glintlab/scene/scene.h"

namespace glintlab {
namespace {

struct QueryInput {
    glm::vec3 wo, wi, h;
    Footprint fp;
};

// Table 1-like settings: (ln N, α, γ°, footprint area).
struct Setting {
    double log_density;
    float alpha;
    float gamma_deg;
    double area;
};
const Setting kSettings[] = {
    {std::log(1e9), 0.1f, 0.5f, 1.0 / (0.6 * 768 * 768 * 256)},   // SPHERE LIGHTS
    {std::log(1e5), 0.81f, 1.0f, 1.0 / (0.3 * 768 * 768 * 256)},  // TWISTED TORUS, sparse
    {std::log(1e8), 0.03f, 1.0f, 1.0 / (0.3 * 768 * 768 * 256)},  // TWISTED TORUS, dense
    {std::log(1e6), 0.1f, 1.0f, 1e-4 / 8.0},                      // scenes/jakob2014_plane.json
};

GlintDesc setting_desc(const Setting& s) {
    GlintDesc d;
    d.model_id = GlintModelId::Jakob2014;
    d.alpha_x = d.alpha_y = s.alpha;
    d.log_density = float(s.log_density);
    Jakob2014Params p;
    p.gamma_deg = s.gamma_deg;
    p.query_area = s.area;
    d.params = p;
    return d;
}

// View directions cosine-distributed, light directions from the model's
// importance sampling (as in `validate jakob2014`'s Table 1 statistics).
std::vector<QueryInput> make_inputs(const GlintDesc& d, double area) {
    std::vector<QueryInput> in;
    Pcg32 rng(7u, 8u);
    const float side = float(std::sqrt(area));
    while (in.size() < 4096) {
        const float r1 = rng.next_float(), r2 = rng.next_float();
        const float sr = std::sqrt(r1), ph = 2.0f * std::numbers::pi_v<float> * r2;
        const glm::vec3 wo(sr * std::cos(ph), sr * std::sin(ph),
                           std::sqrt(std::max(1e-4f, 1.0f - r1)));
        const auto wi =
            jakob2014_sample_wi(d, wo, rng.next_float(), {rng.next_float(), rng.next_float()});
        if (!wi) continue;
        QueryInput q;
        q.wo = wo;
        q.wi = *wi;
        q.h = glm::normalize(wo + *wi);
        q.fp = Footprint{glm::vec2(rng.next_float(), rng.next_float()), glm::vec2(side, 0.0f),
                         glm::vec2(0.0f, side)};
        in.push_back(q);
    }
    return in;
}

void BM_Jakob2014Query(benchmark::State& state) {
    const Setting& s = kSettings[state.range(0)];
    const GlintDesc d = setting_desc(s);
    const std::vector<QueryInput> in = make_inputs(d, s.area);
    jakob2014::thread_stats() = jakob2014::QueryStats{};
    size_t i = 0;
    for (auto _ : state) {
        const QueryInput& q = in[i];
        benchmark::DoNotOptimize(jakob2014_footprint_ndf(q.wo, q.wi, q.h, q.fp, d));
        i = (i + 1) & 4095u;
    }
    const jakob2014::QueryStats& st = jakob2014::thread_stats();
    state.counters["nodes_per_query"] = double(st.nodes) / double(std::max<int64_t>(1, st.queries));
    state.counters["particles_per_query"] = st.particles / double(std::max<int64_t>(1, st.queries));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Jakob2014Query)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

void BM_Jakob2014Pdf(benchmark::State& state) {
    const GlintDesc d = setting_desc(kSettings[3]);
    const std::vector<QueryInput> in = make_inputs(d, kSettings[3].area);
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(jakob2014_pdf(d, in[i].wo, in[i].wi));
        i = (i + 1) & 4095u;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Jakob2014Pdf)->Unit(benchmark::kNanosecond);

// Algorithm 2 for one NDF (fresh table each iteration), and its memory.
void BM_Jakob2014IntegralTable(benchmark::State& state) {
    jakob2014::NdfSpec spec;
    spec.alpha_x = spec.alpha_y = float(state.range(0)) / 1000.0f;
    size_t bytes = 0, entries = 0;
    for (auto _ : state) {
        jakob2014::NdfIntegralTable t(spec);
        bytes = t.memory_bytes();
        entries = t.entries();
        benchmark::DoNotOptimize(entries);
    }
    state.counters["entries"] = double(entries);
    state.counters["bytes"] = double(bytes);
}
BENCHMARK(BM_Jakob2014IntegralTable)
    ->Arg(10)
    ->Arg(30)
    ->Arg(100)
    ->Arg(300)
    ->Arg(810)
    ->Unit(benchmark::kMillisecond);

// One-thread renders of `scene` per iteration, counted in samples.
void render_for(benchmark::State& state, const Scene& scene) {
    const Accelerator accel(scene);
    for (auto _ : state) {
        Image image = render_scene(scene, accel, RenderOptions{1, true});
        benchmark::DoNotOptimize(image.pixels.data());
    }
    state.SetItemsProcessed(state.iterations() * scene.camera.width * scene.camera.height *
                            scene.render.spp);
}

// scenes/jakob2014_plane.json at 192 x 128, 4 spp, one thread: jakob2014 vs
// the same scene with every glint material switched to `smooth`.
void BM_Jakob2014Render(benchmark::State& state, bool smooth) {
    Scene scene =
        load_scene(std::filesystem::path(GLINTLAB_SOURCE_DIR) / "scenes/jakob2014_plane.json");
    scene.camera.width = 192;
    scene.camera.height = 128;
    scene.render.spp = 4;
    if (smooth)
        for (MaterialDesc& m : scene.materials)
            if (m.type == MaterialDesc::Type::Glint) {
                m.glint.model_id = GlintModelId::Smooth;
                m.glint.params = SmoothParams{};
            }
    render_for(state, scene);
}
BENCHMARK_CAPTURE(BM_Jakob2014Render, jakob2014, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Jakob2014Render, smooth, true)->Unit(benchmark::kMillisecond);

// scenes/default.json (five objects, environment map + sun, path tracing,
// 128 x 128, 4 spp, one thread) with its glint material ("gold_flakes",
// smooth in the file) as jakob2014 vs as smooth: a mixed scene where the
// glint model is one material among several, as in 002's comparison.
void BM_Jakob2014DefaultScene(benchmark::State& state, bool smooth) {
    Scene scene = load_scene(std::filesystem::path(GLINTLAB_SOURCE_DIR) / "scenes/default.json");
    scene.camera.width = 128;
    scene.camera.height = 128;
    scene.render.spp = 4;
    scene.render.integrator = RenderSettings::Integrator::Path;
    if (!smooth)
        for (MaterialDesc& m : scene.materials)
            if (m.type == MaterialDesc::Type::Glint) {
                m.glint.model_id = GlintModelId::Jakob2014;
                m.glint.log_density = float(std::log(1e6));
                Jakob2014Params p;
                p.query_area = 1e-4;
                m.glint.params = p;
            }
    render_for(state, scene);
}
BENCHMARK_CAPTURE(BM_Jakob2014DefaultScene, jakob2014, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Jakob2014DefaultScene, smooth, true)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace glintlab
