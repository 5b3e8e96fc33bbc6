// The footprint lookups of a glint's density and roughness maps (256², one
// value each), apart (two lookups) and packed into one texture by
// pack_scalar_inputs (one lookup): docs/BENCHMARKS.md, "Textured parameters".
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "glintlab/core/rng.h"
#include "glintlab/core/texture_input.h"

namespace glintlab {
namespace {

std::shared_ptr<const TextureInput> map_input(uint64_t seed) {
    Pcg32 rng(seed, 0);
    std::vector<float> t(256 * 256);
    for (float& v : t) v = 0.5f + rng.next_float();
    auto in = std::make_shared<TextureInput>();
    in->texture =
        std::make_shared<const MipTexture>(256, 256, 1, std::move(t), TextureWrap::Repeat);
    return in;
}

void BM_DensityAndRoughnessLookup(benchmark::State& state) {
    std::shared_ptr<const TextureInput> density = map_input(1), alpha = map_input(2),
                                        alpha_y = alpha;
    if (state.range(0) != 0) {
        std::shared_ptr<const TextureInput>* inputs[] = {&density, &alpha, &alpha_y};
        pack_scalar_inputs(inputs);
    }
    // Footprints of one to a few texels, 2–3:1 (a plane seen at 25°).
    Pcg32 rng(3, 0);
    std::vector<Footprint> fps(4096);
    for (Footprint& f : fps) {
        const float s = (0.5f + 3.0f * rng.next_float()) / 256.0f;
        f = {{rng.next_float(), rng.next_float()}, {s, 0.0f}, {0.0f, 2.4f * s}};
    }
    const TextureInput* inputs[] = {density.get(), alpha.get(), alpha_y.get()};
    size_t i = 0;
    for (auto _ : state) {
        const Footprint& f = fps[i++ & 4095];
        float values[3] = {0.0f, 0.0f, 0.0f};
        lookup_scalars(inputs, f.uv, &f, values);
        benchmark::DoNotOptimize(values);
    }
}
BENCHMARK(BM_DensityAndRoughnessLookup)->ArgName("packed")->Arg(0)->Arg(1);

}  // namespace
}  // namespace glintlab
