// kneiphof2025 (003) on the GPU: the hooks of glints/gpu_model_hooks.h over
// Kneiphof2025Resources (kneiphof2025_gpu.h). Option "dynamic_environment":
// the environment prefiltered on the GPU in every frame (003 §5 "dynamic
// IBL", compute passes) instead of once on the CPU. Option
// "dynamic_full_resolution": that prefilter with every layer filtered at
// full resolution (the CPU's values) instead of the default reduced grids of
// the rough layers (kneiphof2025_prefilter_gpu.h, Resolution).
#include "glintlab/glints/gpu_model_hooks.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_gpu.h"

namespace glintlab {
namespace {

constexpr unsigned kDynamicEnvironment = 1u << 0;     // options[0]
constexpr unsigned kDynamicFullResolution = 1u << 1;  // options[1]

constexpr GpuModelOption kOptions[] = {
    {"dynamic_environment",
     "prefilter the environment on the GPU in every frame (003 5, dynamic IBL) instead of once "
     "on the CPU",
     false},
    {"dynamic_full_resolution",
     "dynamic environment: filter every prefiltered layer at full resolution (the CPU's values) "
     "instead of the rough layers on coarser grids, upsampled (the faster default)",
     false},
};

std::string glue_path(unsigned) {
    return "glintlab/glints/kneiphof2025/kneiphof2025_gpu.glsl";
}

class State final : public GpuModelState {
  public:
    void begin_frame(const GpuFrame& f, unsigned options) override {
        resources_.set_dynamic((options & kDynamicEnvironment) != 0,
                               (options & kDynamicFullResolution) != 0);
        if (f.environment_texture == 0) return;
        resources_.begin_frame(f.scene, f.environment_texture, f.environment_width,
                               f.environment_height, f.environment_scale);
    }
    void prepare(unsigned program, gl::UniformCache& u, const GlintDesc& desc, const GpuFrame& f,
                 unsigned options) override {
        resources_.set_dynamic((options & kDynamicEnvironment) != 0,
                               (options & kDynamicFullResolution) != 0);
        resources_.prepare(program, u, f.scene, desc, f.environment_scale,
                           f.environment_rotation_rad);
    }

  private:
    gl::Kneiphof2025Resources resources_;  // prefiltered environment, DFG table
};

}  // namespace

const GpuModelHooks& kneiphof2025_gpu_hooks() {
    static const GpuModelHooks hooks{GlintModelId::Kneiphof2025, glue_path, kOptions,
                                     [] { return std::unique_ptr<GpuModelState>(new State); }};
    return hooks;
}

}  // namespace glintlab
