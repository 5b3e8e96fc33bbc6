// Tile-parallel rendering of a scene on the CPU. Deterministic: every pixel
// has its own sample stream (core/rng.h pixel_stream), so the same seed gives
// a bit-identical image for any thread count and tile order.
#pragma once

#include <functional>

#include "glintlab/core/image.h"
#include "glintlab/scene/scene.h"

namespace glintlab {

struct RenderOptions {
    RenderOptions() = default;
    // RenderOptions{threads, quiet} as before the progress hook.
    RenderOptions(int threads_, bool quiet_) : threads(threads_), quiet(quiet_) {}

    int threads = 0;     // 0: all cores
    bool quiet = false;  // no progress bar
    // Optional: called with the fraction of tiles done (0, 1] after each
    // tile, from whichever render thread finished it (concurrently; the
    // callee synchronises). The Python module's progress hook.
    std::function<void(double)> progress;
};

class Accelerator;

// Builds the scene's Embree BVH, then renders.
Image render_scene(const Scene& scene, const RenderOptions& options);
// Renders with a BVH built beforehand from the same scene's shapes (benchmarks
// time frames without the build; materials and lights may differ).
Image render_scene(const Scene& scene, const Accelerator& accel, const RenderOptions& options);

}  // namespace glintlab
