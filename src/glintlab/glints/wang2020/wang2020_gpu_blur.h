// The post-process of wang2020 (001 §4.4 "Gaussian Blurring") as compute
// passes, the GPU counterpart of glints/wang2020/wang2020_postprocess.h:
//   δ = G9 * visibility,  out = G3 * (rgb · δ)
// on an RGBA32F glint buffer (rgb glints, a = directional-occlusion
// visibility), separable, σ = size / 6, borders clamped to the edge, the
// same normalised taps as gaussian_blur. Four passes: δ along x, δ along y,
// rgb·δ along x, along y (the last also stores δ in a).
//
// GpuRenderer runs it on the glint layer of its forward pass (wang2020
// materials with "blur" on, under an environment) and adds the result into
// its colour target (apply_add), as render_scene does with
// postprocess_glints; the forward pass has no directional occlusion, so its
// visibility is 1 (δ = 1) where the CPU traces a ray. Tested against
// postprocess_glints and timed by `bench --gpu`.
#pragma once

#include <memory>

#include "glintlab/glints/wang2020/wang2020_postprocess.h"

namespace glintlab::gl {

class GpuWang2020Blur {
  public:
    GpuWang2020Blur();  // needs a current OpenGL 4.5 context; compiles the pass
    ~GpuWang2020Blur();
    GpuWang2020Blur(const GpuWang2020Blur&) = delete;
    GpuWang2020Blur& operator=(const GpuWang2020Blur&) = delete;

    // Blurs the RGBA32F texture `glints` (width x height); returns the
    // RGBA32F result texture (owned, valid until the next call). Sizes odd,
    // in [1, 31] (glintlab::Error otherwise).
    unsigned apply(unsigned glints, int width, int height, int occlusion_size = 9,
                   int glint_size = 3);
    // apply(), then adds the rgb of the result to the rgb of the RGBA32F
    // texture `target` (same size; its alpha is kept).
    void apply_add(unsigned glints, unsigned target, int width, int height, int occlusion_size = 9,
                   int glint_size = 3);
    // Upload, apply, read back (tests).
    wang2020::GlintBuffer apply(const wang2020::GlintBuffer& in, int occlusion_size = 9,
                                int glint_size = 3);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace glintlab::gl
