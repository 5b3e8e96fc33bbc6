#include "glintlab/render/renderer.h"

#include <atomic>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "glintlab/core/progress.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/glint_lighting.h"
#include "glintlab/glints/wang2020/wang2020_model.h"
#include "glintlab/glints/wang2020/wang2020_postprocess.h"
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
    // Radiance deferred to wang2020's §4.4 image pass (glint_lighting.h):
    // per pixel the mean over samples of the glint layer (rgb) and of the
    // directional-occlusion visibility (w); pixels no model wrote keep
    // rgb = 0 and visibility 1, so they neither add glints nor darken a
    // neighbour's occlusion blur.
    wang2020::GlintBuffer post;
    post.width = width;
    post.height = height;
    post.texels.assign(static_cast<size_t>(width) * static_cast<size_t>(height),
                       glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    std::atomic<bool> any_post{false};
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
                        glm::dvec4 post_sum(0.0);
                        bool post_active = false;
                        for (int s = 0; s < spp; ++s) {
                            glm::vec2 jitter(0.5f);
                            if (spp > 1) jitter = {rng.next_float(), rng.next_float()};
                            const RayDifferential ray = camera.generate(
                                glm::vec2(static_cast<float>(x), static_cast<float>(y)) + jitter);
                            GlintPostSample ps;
                            const glm::vec3 L = path ? integrate_path(ctx, ray, rng, &ps)
                                                     : integrate_direct(ctx, ray, rng, &ps);
                            sum += glm::dvec3(L);
                            post_sum += glm::dvec4(glm::dvec3(ps.rgb), ps.visibility);
                            post_active = post_active || ps.active;
                        }
                        image.at(x, y) = glm::vec3(sum / static_cast<double>(spp));
                        if (post_active) {
                            post.texels[static_cast<size_t>(y) * static_cast<size_t>(width) +
                                        static_cast<size_t>(x)] =
                                glm::vec4(post_sum / static_cast<double>(spp));
                            any_post.store(true, std::memory_order_relaxed);
                        }
                    }
                progress.update();
                if (options.progress)
                    options.progress(static_cast<double>(progress.work_done()) /
                                     static_cast<double>(tiles_x * tiles_y));
            }
        });
    progress.done();
    if (any_post.load()) {
        // 001 §4.4: δ = G9 * visibility, glints = G3 * (rgb · δ) where
        // "glint_blur" asks for it (at 1 spp under "auto"), else rgb · δ.
        const wang2020::GlintBuffer blurred =
            wang2020::postprocess_glints(post, 9, wang2020_glint_blur_taps(scene, spp == 1));
        for (size_t i = 0; i < image.pixels.size(); ++i)
            image.pixels[i] += glm::vec3(blurred.texels[i]);
    }
    return image;
}

}  // namespace glintlab
