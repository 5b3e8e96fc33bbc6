// Facets enumerated per second by the explicit ground truth, and where it gets
// slow: one shading query (enumeration + count in the γ cone, or the
// environment sum) for footprints holding 1e2 ... 1e6 facets in expectation,
// at 1e9 facets per unit uv area (log_density ln 1e9), Beckmann α = 0.3.
// Footprints are squares at pre-generated random positions (cycled), so the
// quadtree descent to a new place is part of every query. The counter
// `facets/s` is the enumeration throughput; the time per iteration is the
// cost of one shading call for that footprint size.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "glintlab/core/rng.h"
#include "glintlab/glints/explicit/explicit.h"

namespace glintlab {
namespace {

ExplicitFacetField bench_field() {
    ExplicitFacetField f;
    f.log_density = std::log(1.0e9);
    f.max_facets_per_footprint = 1e8;
    return f;
}

std::vector<Footprint> footprints(double expected_facets) {
    std::vector<Footprint> fps;
    Pcg32 rng(5u, 6u);
    const float side = float(std::sqrt(expected_facets / 1.0e9));
    for (int i = 0; i < 256; ++i)
        fps.push_back(Footprint{glm::vec2(rng.next_float(), rng.next_float()),
                                glm::vec2(side, 0.0f), glm::vec2(0.0f, side)});
    return fps;
}

void BM_ExplicitEnumerate(benchmark::State& state) {
    const ExplicitFacetField field = bench_field();
    const auto fps = footprints(double(state.range(0)));
    uint64_t total = 0;
    size_t i = 0;
    for (auto _ : state) {
        total += for_each_explicit_facet(
            field, fps[i], [](const ExplicitFacet& f) { benchmark::DoNotOptimize(f.m.z); });
        i = (i + 1) & 255u;
    }
    state.counters["facets/s"] = benchmark::Counter(double(total), benchmark::Counter::kIsRate);
}

void BM_ExplicitCount(benchmark::State& state) {
    const ExplicitFacetField field = bench_field();
    const auto fps = footprints(double(state.range(0)));
    const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f));
    const glm::vec3 wi = glm::normalize(glm::vec3(-0.3f, 0.0f, 1.0f));
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(
            explicit_footprint_ndf(field, fps[i], wo, wi, std::numbers::pi_v<float> / 180.0f));
        i = (i + 1) & 255u;
    }
    state.counters["facets/s"] = benchmark::Counter(
        double(state.iterations()) * double(state.range(0)), benchmark::Counter::kIsRate);
}

void BM_ExplicitEnvironment(benchmark::State& state) {
    const ExplicitFacetField field = bench_field();
    const auto fps = footprints(double(state.range(0)));
    const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f));
    const auto env = [](glm::vec3 d) { return glm::vec3(1.0f + d.x, 1.0f, 1.0f + d.z); };
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(explicit_environment_radiance(field, fps[i], wo, env));
        i = (i + 1) & 255u;
    }
    state.counters["facets/s"] = benchmark::Counter(
        double(state.iterations()) * double(state.range(0)), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_ExplicitEnumerate)
    ->Name("explicit/enumerate")
    ->RangeMultiplier(10)
    ->Range(100, 1000000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ExplicitCount)
    ->Name("explicit/count_ndf")
    ->RangeMultiplier(10)
    ->Range(100, 1000000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ExplicitEnvironment)
    ->Name("explicit/environment")
    ->RangeMultiplier(10)
    ->Range(100, 1000000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace glintlab
