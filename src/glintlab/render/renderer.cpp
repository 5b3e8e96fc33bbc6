#include "glintlab/render/renderer.h"

#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "glintlab/core/progress.h"
#include "glintlab/core/rng.h"
#include "glintlab/render/accel.h"
#include "glintlab/render/integrators.h"

namespace glintlab {
namespace {

constexpr int kTileSize = 16;

}  // namespace

Image render_scene(const Scene& scene, const RenderOptions& options) {
    const Accelerator accel(scene);
    return render_scene(scene, accel, options);
}

Image render_scene(const Scene& scene, const Accelerator& accel, const RenderOptions& options) {
    const Camera& camera = scene.camera;
    const int width = camera.width, height = camera.height;
    const int spp = scene.render.spp;
    const bool path = scene.render.integrator == RenderSettings::Integrator::Path;
    // One sample per pixel looks at the pixel centre with the whole pixel's
    // footprint, like a real-time shader. With several samples, positions are
    // jittered over the pixel; the path integrator then shrinks footprints by
    // max(1/8, 1/√spp) (pbrt-v4) since the samples themselves integrate over
    // the pixel, while the direct integrator keeps whole-pixel footprints.
    const float diff_scale =
        (path && spp > 1) ? std::max(0.125f, 1.0f / std::sqrt(static_cast<float>(spp))) : 1.0f;
    const IntegratorContext ctx{scene, accel, diff_scale};

    Image image(width, height);
    const int tiles_x = (width + kTileSize - 1) / kTileSize;
    const int tiles_y = (height + kTileSize - 1) / kTileSize;
    ProgressReporter progress(static_cast<int64_t>(tiles_x) * tiles_y, "render", options.quiet);
    std::unique_ptr<tbb::global_control> limit;
    if (options.threads > 0)
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      static_cast<size_t>(options.threads));
    tbb::parallel_for(
        tbb::blocked_range<int>(0, tiles_x * tiles_y, 1), [&](const tbb::blocked_range<int>& r) {
            for (int tile = r.begin(); tile != r.end(); ++tile) {
                const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
                for (int y = y0; y < std::min(y0 + kTileSize, height); ++y)
                    for (int x = x0; x < std::min(x0 + kTileSize, width); ++x) {
                        Pcg32 rng = pixel_stream(x, y, scene.render.seed);
                        glm::dvec3 sum(0.0);
                        for (int s = 0; s < spp; ++s) {
                            glm::vec2 jitter(0.5f);
                            if (spp > 1) jitter = {rng.next_float(), rng.next_float()};
                            const RayDifferential ray = camera.generate(
                                glm::vec2(static_cast<float>(x), static_cast<float>(y)) + jitter);
                            const glm::vec3 L = path ? integrate_path(ctx, ray, rng)
                                                     : integrate_direct(ctx, ray, rng);
                            sum += glm::dvec3(L);
                        }
                        image.at(x, y) = glm::vec3(sum / static_cast<double>(spp));
                    }
                progress.update();
            }
        });
    progress.done();
    return image;
}

}  // namespace glintlab
