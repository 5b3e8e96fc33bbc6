// zirr2016 (Zirr & Kaplanyan 2016) on the GPU: the hooks of
// glints/gpu_model_hooks.h (glue zirr2016_gpu.glsl, the model's uniforms).
#include <variant>

#include <epoxy/gl.h>

#include "glintlab/gl/uniform_cache.h"
#include "glintlab/glints/glint_desc.h"
#include "glintlab/glints/gpu_model_hooks.h"

namespace glintlab {
namespace {

std::string glue_path(unsigned) {
    return "glintlab/glints/zirr2016/zirr2016_gpu.glsl";
}

class State final : public GpuModelState {
  public:
    void prepare(unsigned program, gl::UniformCache& u, const GlintDesc& desc, const GpuFrame&,
                 unsigned) override {
        auto loc = [&](const char* name) { return u.location(program, name); };
        const auto& p = std::get<Zirr2016Params>(desc.params);
        glProgramUniform1f(program, loc("u_zirr2016_microfacet_roughness"), p.microfacet_roughness);
        glProgramUniform1f(program, loc("u_zirr2016_max_anisotropy"), p.max_anisotropy);
        glProgramUniform1f(program, loc("u_zirr2016_screen_space_scale"), p.screen_space_scale);
    }
};

}  // namespace

const GpuModelHooks& zirr2016_gpu_hooks() {
    static const GpuModelHooks hooks{GlintModelId::Zirr2016, glue_path, {}, [] {
                                         return std::unique_ptr<GpuModelState>(new State);
                                     }};
    return hooks;
}

}  // namespace glintlab
