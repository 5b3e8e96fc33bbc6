// Bloom on the GPU for the viewer's display: the same filter as
// core/bloom.h apply_bloom (bright-pass extraction, the mean of four
// octave-spaced Gaussians with scatter-normalised borders, energy-conserving
// composite), as compute passes, so the window shows what the PNG will hold.
// Tested against apply_bloom (gpu_renderer_test.cpp).
#pragma once

#include <memory>

#include "glintlab/core/bloom.h"

namespace glintlab::gl {

class GpuBloom {
  public:
    GpuBloom();  // needs a current OpenGL 4.5 context; compiles the passes
    ~GpuBloom();
    GpuBloom(const GpuBloom&) = delete;
    GpuBloom& operator=(const GpuBloom&) = delete;

    // Applies `settings` to the RGBA32F texture `hdr` (width x height) and
    // returns the RGBA32F texture holding the result (owned by this object,
    // valid until the next call). strength 0 returns `hdr` itself.
    unsigned apply(unsigned hdr, int width, int height, const BloomSettings& settings);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace glintlab::gl
