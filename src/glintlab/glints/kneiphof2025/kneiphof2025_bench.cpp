// CPU cost of kneiphof2025 (003) per shaded footprint, next to deliot2023
// under one directional light in the same run (003 Table 1 compares the same
// pair on the GPU), and the cost of one environment prefilter pass (the
// "dynamic IBL" case: partition, K + 3 channels, 7 roughness levels).
// Inputs (random footprints of 1-8 anisotropy with 1e2-1e5 facets, GGX
// alpha = 0.3, views and mirror directions) are pre-generated and cycled.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "glintlab/core/image.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/deliot2023/deliot2023.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"
#include "glintlab/microfacet/microfacet.h"
#include "glintlab/scene/environment.h"
#include "glintlab/scene/scene.h"

namespace glintlab {
namespace {

const char* const kForest = "/usr/share/blender/datafiles/studiolights/world/forest.exr";

struct Inputs {
    std::vector<glm::vec3> h, wo, wi, wr;
    std::vector<Footprint> fp;
    std::vector<float> log_density;
    std::vector<uint32_t> seed;
    Inputs() {
        Pcg32 rng(3u, 4u);
        for (int i = 0; i < 1024; ++i) {
            const glm::vec3 o =
                glm::normalize(glm::vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, 1.0f));
            const glm::vec3 l =
                glm::normalize(glm::vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, 1.0f));
            wo.push_back(o);
            wi.push_back(l);
            h.push_back(glm::normalize(o + l));
            const float z = 2.0f * rng.next_float() - 1.0f, phi = 6.2831853f * rng.next_float();
            wr.push_back(glm::vec3(std::sqrt(1.0f - z * z) * std::cos(phi), z,
                                   std::sqrt(1.0f - z * z) * std::sin(phi)));
            const float a = 3.14159265f * rng.next_float();
            const float minor = 1e-3f, ratio = std::exp2(3.0f * rng.next_float());
            fp.push_back(Footprint{glm::vec2(rng.next_float(), rng.next_float()),
                                   glm::vec2(std::cos(a), std::sin(a)) * (minor * ratio),
                                   glm::vec2(-std::sin(a), std::cos(a)) * minor});
            log_density.push_back(18.0f + 7.0f * rng.next_float());
            seed.push_back(rng.next_uint());
        }
    }
};

const Inputs& inputs() {
    static const Inputs in;
    return in;
}

std::shared_ptr<const EnvironmentMap> forest() {
    static const auto env = std::make_shared<const EnvironmentMap>(read_image(kForest), 1.0f, 0.0f);
    return env;
}

GlintDesc desc_for(int levels) {
    GlintDesc d;
    d.model_id = GlintModelId::Kneiphof2025;
    d.ndf = NdfType::GGX;
    d.alpha_x = d.alpha_y = 0.3f;
    Kneiphof2025Params p;
    p.levels = levels;
    d.params = p;
    return d;
}

// deliot2023 under one directional light: D_P(h) and the rest of the BRDF
// (G2, F = 1) for one light direction, i.e. what a pixel pays per light.
void BM_Deliot2023Directional(benchmark::State& state) {
    const Inputs& in = inputs();
    Deliot2023Target t;
    t.ndf = shader::NDF_GGX;
    t.alpha_x = t.alpha_y = 0.3f;
    const Deliot2023Params params;
    size_t i = 0;
    for (auto _ : state) {
        t.log_density = in.log_density[i];
        t.seed = in.seed[i];
        const float d = deliot2023_ndf(in.h[i], in.fp[i], t, params);
        const float g = shader::G2_SmithCorrelated(shader::NDF_GGX, in.wo[i], in.wi[i], 0.3f, 0.3f);
        benchmark::DoNotOptimize(d * g / (4.0f * in.wo[i].z));
        i = (i + 1) & 1023u;
    }
}
BENCHMARK(BM_Deliot2023Directional)->Name("kneiphof2025/deliot2023_directional");

// kneiphof2025 under the environment (Eq. 17): LUT, the smooth term (003's
// split sum, the default: 1 fetch; or the lobe estimate: 32 reads of the
// prefiltered radiance), the weights' fetch, 12 multinomials of K bins.
void BM_Kneiphof2025Environment(benchmark::State& state) {
    const Inputs& in = inputs();
    const int K = static_cast<int>(state.range(0));
    const auto env = kneiphof2025_environment_for(forest(), K, 1e-2f);
    GlintDesc d = desc_for(K);
    std::get<Kneiphof2025Params>(d.params).smooth = state.range(1) != 0
                                                        ? Kneiphof2025Params::Smooth::Lobe
                                                        : Kneiphof2025Params::Smooth::SplitSum;
    size_t i = 0;
    for (auto _ : state) {
        d.log_density = in.log_density[i];
        d.seed = in.seed[i];
        benchmark::DoNotOptimize(
            kneiphof2025_environment_radiance(*env, in.wr[i], in.wr[i], in.wo[i].z, in.fp[i], d));
        i = (i + 1) & 1023u;
    }
}
BENCHMARK(BM_Kneiphof2025Environment)
    ->Name("kneiphof2025/environment")
    ->ArgNames({"K", "lobe"})
    ->Args({4, 0})
    ->Args({8, 0})
    ->Args({4, 1})
    ->Args({8, 1});

// The wang2020-style variant (K = 1 on the grid without h).
void BM_Kneiphof2025Wang(benchmark::State& state) {
    const Inputs& in = inputs();
    const auto env = kneiphof2025_environment_for(forest(), 4, 1e-2f);
    GlintDesc d = desc_for(4);
    std::get<Kneiphof2025Params>(d.params).variant = Kneiphof2025Params::Variant::Wang2020Style;
    size_t i = 0;
    for (auto _ : state) {
        d.log_density = in.log_density[i];
        d.seed = in.seed[i];
        benchmark::DoNotOptimize(
            kneiphof2025_environment_radiance(*env, in.wr[i], in.wr[i], in.wo[i].z, in.fp[i], d));
        i = (i + 1) & 1023u;
    }
}
BENCHMARK(BM_Kneiphof2025Wang)->Name("kneiphof2025/wang2020_style");

// One K = 1 area-light factor (the sun, sphere lights) without the cone
// quadrature: the grid walk only, comparable to deliot2023's D_P.
void BM_Kneiphof2025AreaFactor(benchmark::State& state) {
    const Inputs& in = inputs();
    GlintDesc d = desc_for(4);
    size_t i = 0;
    for (auto _ : state) {
        d.log_density = in.log_density[i];
        d.seed = in.seed[i];
        benchmark::DoNotOptimize(kneiphof2025_area_factor(in.h[i], in.fp[i], 1e-3f, d));
        i = (i + 1) & 1023u;
    }
}
BENCHMARK(BM_Kneiphof2025AreaFactor)->Name("kneiphof2025/area_factor");

// One prefilter pass of forest.exr into 7 levels of 256 x 128 (the mirror
// and 6 filtered levels, 64 samples per texel; all cores).
void BM_Kneiphof2025Prefilter(benchmark::State& state) {
    const auto env = forest();
    Kneiphof2025PrefilterOptions o;
    o.levels = static_cast<int>(state.range(0));
    for (auto _ : state) {
        Kneiphof2025Environment e(*env, o);
        benchmark::DoNotOptimize(e.radiance_levels());
    }
}
BENCHMARK(BM_Kneiphof2025Prefilter)
    ->Name("kneiphof2025/prefilter")
    ->Arg(4)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace glintlab
