// CPU rendering throughput: the default-scene materials at 128x128 under an
// environment and a sun, per integrator. Reported as time per frame and
// samples (camera paths) per second.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/renderer.h"

namespace glintlab {
namespace {

Scene bench_scene(const char* integrator) {
    Scene scene = load_scene(std::filesystem::path(GLINTLAB_SOURCE_DIR) / "scenes/default.json");
    scene.camera.width = 128;
    scene.camera.height = 128;
    scene.render.spp = 4;
    scene.render.integrator = std::string(integrator) == "path"
                                  ? RenderSettings::Integrator::Path
                                  : RenderSettings::Integrator::Direct;
    return scene;
}

void BM_RenderDefaultScene(benchmark::State& state, const char* integrator) {
    const Scene scene = bench_scene(integrator);
    const int threads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        Image image = render_scene(scene, RenderOptions{threads, true});
        benchmark::DoNotOptimize(image.pixels.data());
    }
    state.SetItemsProcessed(state.iterations() * scene.camera.width * scene.camera.height *
                            scene.render.spp);
}

BENCHMARK_CAPTURE(BM_RenderDefaultScene, direct, "direct")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RenderDefaultScene, path, "path")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace glintlab
