// The smooth glint model (D_P = D) on the GPU: the hooks of
// glints/gpu_model_hooks.h. Option "split_sum_environment": under an
// environment, shade the smooth material as a real-time engine does, with
// one split-sum lookup of a GGX-prefiltered radiance map (glue
// smooth_split_sum_gpu.glsl over kneiphof2025's prefiltered maps and DFG
// table, kneiphof2025_gpu.h), instead of the forward pass's 48-sample filtered
// importance sampling that follows the CPU reference. Off by default (the
// GPU image then matches the CPU's); `glintlab bench --gpu` turns it on, so
// the benches compare the glint models with the baseline an engine ships.
#include <variant>

#include "glintlab/core/error.h"
#include "glintlab/glints/glint_desc.h"
#include "glintlab/glints/gpu_model_hooks.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_gpu.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_params.h"
#include "glintlab/scene/scene.h"

namespace glintlab {
namespace {

constexpr unsigned kSplitSumEnvironment = 1u << 0;  // options[0]

constexpr GpuModelOption kOptions[] = {
    {"split_sum_environment",
     "under an environment, one split-sum lookup of a GGX-prefiltered map (the engine baseline) "
     "instead of the filtered importance sampling that follows the CPU reference",
     true},
};

std::string glue_path(unsigned options) {
    return (options & kSplitSumEnvironment) != 0 ? "glintlab/glints/smooth_split_sum_gpu.glsl"
                                                 : "glintlab/glints/smooth_gpu.glsl";
}

class State final : public GpuModelState {
  public:
    void prepare(unsigned program, gl::UniformCache& u, const GlintDesc& desc, const GpuFrame& f,
                 unsigned options) override {
        if ((options & kSplitSumEnvironment) == 0 || f.scene.environment < 0) return;
        if (desc.has_base())
            fail(
                "GPU option split_sum_environment of the smooth model: a material with a "
                "diffuse base (\"base_albedo\") is not supported (the split sum shades the "
                "specular lobe only); turn the option off for this scene");
        // kneiphof2025's maps at its default K and black level (only the
        // radiance layers and the DFG table are read): the same CPU prefilter
        // and cache as a kneiphof2025 material of the scene.
        GlintDesc k = desc;
        k.model_id = GlintModelId::Kneiphof2025;
        k.params = Kneiphof2025Params{};
        resources_.prepare(program, u, f.scene, k, f.environment_scale, f.environment_rotation_rad);
    }

  private:
    gl::Kneiphof2025Resources resources_;
};

}  // namespace

const GpuModelHooks& smooth_gpu_hooks() {
    static const GpuModelHooks hooks{GlintModelId::Smooth, glue_path, kOptions,
                                     [] { return std::unique_ptr<GpuModelState>(new State); }};
    return hooks;
}

}  // namespace glintlab
