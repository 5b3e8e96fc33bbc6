// wang2020 (001) on the GPU: the hooks of glints/gpu_model_hooks.h over
// Wang2020Resources (wang2020_gpu.h: the tables as SSBOs, the uniforms).
#include <memory>
#include <variant>

#include "glintlab/glints/glint_desc.h"
#include "glintlab/glints/gpu_model_hooks.h"
#include "glintlab/glints/wang2020/wang2020_gpu.h"
#include "glintlab/glints/wang2020/wang2020_gpu_blur.h"
#include "glintlab/glints/wang2020/wang2020_model.h"

namespace glintlab {
namespace {

// "blur" (default on): the environment glints go through §4.4's blurs (the
// glint kernel by "glint_blur", wang2020_glint_blur_taps).
bool uses_glint_layer(const GlintDesc& desc) {
    const auto* p = std::get_if<Wang2020Params>(&desc.params);
    return p != nullptr && p->blur;
}

std::string glue_path(unsigned) {
    return "glintlab/glints/wang2020/wang2020_gpu.glsl";
}

class State final : public GpuModelState {
  public:
    // The glint blur's kernel is the scene's (every wang2020 material must
    // agree): once per frame, one sample per pixel.
    void begin_frame(const GpuFrame& f, unsigned) override {
        glint_taps_ = wang2020_glint_blur_taps(f.scene, true);
    }
    void prepare(unsigned program, gl::UniformCache& u, const GlintDesc& desc, const GpuFrame& f,
                 unsigned) override {
        resources_.bind(program, u, desc, f.scene);
    }
    // 001 §4.4's blurs of the deferred environment glints, added into the
    // colour target (render_scene's postprocess_glints).
    void post_pass(unsigned glint_layer, unsigned color, int width, int height) override {
        if (!blur_) blur_ = std::make_unique<gl::GpuWang2020Blur>();
        blur_->apply_add(glint_layer, color, width, height, 9, glint_taps_);
    }

  private:
    gl::Wang2020Resources resources_;
    std::unique_ptr<gl::GpuWang2020Blur> blur_;  // compiled on first use
    int glint_taps_ = 1;                         // "glint_blur" of the frame's scene
};

}  // namespace

const GpuModelHooks& wang2020_gpu_hooks() {
    static const GpuModelHooks hooks{GlintModelId::Wang2020,
                                     glue_path,
                                     {},
                                     [] { return std::unique_ptr<GpuModelState>(new State); },
                                     uses_glint_layer};
    return hooks;
}

}  // namespace glintlab
