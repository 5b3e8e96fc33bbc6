// Per-pass CPU costs of wang2020 (001 Table 3 passes: quadtree, DPF gamma
// accumulation, environment prefilter; plus DPF generation (§4.4, 18 s in the
// paper) and the per-pixel glint evaluation at each of the three scales).
// Heavy passes run once (Iterations(1)); the memory of each table is reported
// as a counter (bytes).
#include <benchmark/benchmark.h>

#include <cmath>

#include "glintlab/glints/wang2020/wang2020_beckmann.h"
#include "glintlab/glints/wang2020/wang2020_dpf.h"
#include "glintlab/glints/wang2020/wang2020_prefilter.h"
#include "glintlab/glints/wang2020/wang2020_quadtree.h"
#include "glintlab/glints/wang2020/wang2020_shading.h"

namespace glintlab::wang2020 {
namespace {

constexpr double kDeg = kPi / 180.0;

glm::vec3 sky(const glm::dvec3& d) {  // smooth test environment
    return glm::vec3(0.5f + 0.5f * static_cast<float>(d.z), 0.7f,
                     1.0f - 0.3f * static_cast<float>(d.x));
}

void BM_Wang2020DpfGeneration(benchmark::State& state) {  // 8 tables, Table 2 res
    for (auto _ : state) {
        size_t bytes = 0;
        for (double a : kRoughnessSet)
            bytes += generate_dpf_table(a, kDeg, {90, 90, 180}).memory_bytes();
        state.counters["bytes"] = static_cast<double>(bytes);
    }
}
BENCHMARK(BM_Wang2020DpfGeneration)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_Wang2020GammaAccumulation(benchmark::State& state) {  // α 0.1, γ 6°
    const int r = static_cast<int>(state.range(0));
    const DpfSet& set = dpf_set({r, r, 2 * r});
    for (auto _ : state) benchmark::DoNotOptimize(extract_dpf(set, 0.1, 6 * kDeg));
}
BENCHMARK(BM_Wang2020GammaAccumulation)
    ->Arg(30)
    ->Arg(45)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

void BM_Wang2020Quadtree(benchmark::State& state) {  // depth 11 (§6)
    for (auto _ : state) {
        const ParticleQuadtree t(static_cast<uint64_t>(state.range(0)), 11, 1);
        state.counters["bytes"] = static_cast<double>(t.memory_bytes());
        state.counters["nodes"] = static_cast<double>(t.nodes().size());
    }
}
BENCHMARK(BM_Wang2020Quadtree)
    ->Arg(100000)
    ->Arg(1000000)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

void BM_Wang2020Prefilter(benchmark::State& state) {  // Snow/Cloth res 10×18×4×12, K = 64
    const DpfSet& set = dpf_set({90, 90, 180});
    const DpfTable dpf = extract_dpf(set, 0.6, kDeg);
    for (auto _ : state) {
        const PrefilterTable t(dpf, 0.6, kDeg, sky, {10, 18, 4, 12}, 64);
        state.counters["bytes"] = static_cast<double>(t.memory_bytes());
    }
}
BENCHMARK(BM_Wang2020Prefilter)->Iterations(1)->Unit(benchmark::kMillisecond);

// Per-pixel glint evaluation at each scale (footprint side chosen so that
// N a(A) = 1 (micro), 16 (meso), 1024 (macro)), N = 10^6, α = 0.6, γ = 6°.
void BM_Wang2020GlintEval(benchmark::State& state) {
    static const Wang2020Model model = [] {
        Wang2020Material m;
        m.alpha = 0.6;
        m.gamma_deg = 6.0;
        m.particles = 1000000;
        m.dpf_res = {30, 30, 60};
        Wang2020Model w(m);
        w.prefilter(sky);
        return w;
    }();
    const double side = std::sqrt(static_cast<double>(state.range(0)) / 1e6);
    const glm::dvec3 n(0, 0, 1), o = spherical_dir(0.5, 0.3);
    double u = 0.0;
    for (auto _ : state) {
        u = std::fmod(u + 0.618034, 1.0);
        const UvBox A{{u, 1.0 - u}, {u + side, 1.0 - u + side}};
        benchmark::DoNotOptimize(model.environment_radiance(A, n, o));
    }
}
BENCHMARK(BM_Wang2020GlintEval)->Arg(1)->Arg(16)->Arg(1024);

}  // namespace
}  // namespace glintlab::wang2020
