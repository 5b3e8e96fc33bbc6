// Reading environment maps from files: the rules on texel values
// (docs/SCENE_FORMAT.md, lights). Kept apart from environment.h, which
// every module including scene.h sees.
#pragma once

#include <cstddef>
#include <filesystem>

#include "glintlab/core/image.h"

namespace glintlab {

// Largest environment radiance accepted, for a texel and for a texel times
// the light's scale. Single precision overflows at 3.4e38: the sampling
// distribution sums luminance·sinθ over all texels (≤ 1e9 of them), the
// prefiltered maps of the glint models sum texels over mip levels, and a
// render multiplies radiance by path throughput / pdf and accumulates up to
// 2²⁰ samples per pixel. 1e20 leaves 18 orders of magnitude of headroom for
// those sums and products while real HDR captures peak around 1e5–1e9 (the
// sun's disc).
inline constexpr float kMaxEnvironmentRadiance = 1e20f;

// Reads a lat-long environment image (read_image: non-finite texels are an
// error naming the file and the texel). Negative components, which HDR tools
// produce by ringing of resampling filters and which are not radiance, are
// clamped to 0: the number of texels touched goes to *negative_texels and,
// when non-zero, one warning line naming the file and the count to stderr.
// A texel whose largest component, or that times `scale`, exceeds
// kMaxEnvironmentRadiance is an error naming the file, the texel and the limit.
Image read_environment_image(const std::filesystem::path& path, float scale,
                             size_t* negative_texels = nullptr);

}  // namespace glintlab
