// The table of GpuModelHooks (gpu_model_hooks.h): the one place that lists
// the models the OpenGL renderer implements.
#include <algorithm>
#include <array>

#include "glintlab/glints/gpu_model_hooks.h"

namespace glintlab {

// Defined beside each model (glints/<model>/<model>_gpu*.cpp).
const GpuModelHooks& smooth_gpu_hooks();
const GpuModelHooks& deliot2023_gpu_hooks();
const GpuModelHooks& zirr2016_gpu_hooks();
const GpuModelHooks& chermain2020_gpu_hooks();
const GpuModelHooks& kneiphof2025_gpu_hooks();
const GpuModelHooks& wang2020_gpu_hooks();

void GpuModelState::begin_frame(const GpuFrame&, unsigned) {}
void GpuModelState::post_pass(unsigned, unsigned, int, int) {}

unsigned GpuModelHooks::program_option_mask() const {
    unsigned mask = 0;
    for (size_t i = 0; i < options.size(); ++i)
        if (options[i].changes_program) mask |= 1u << i;
    return mask;
}

int GpuModelHooks::option_index(std::string_view name) const {
    for (size_t i = 0; i < options.size(); ++i)
        if (options[i].name == name) return static_cast<int>(i);
    return -1;
}

std::span<const GpuModelHooks> gpu_model_hooks() {
    static const std::array<GpuModelHooks, 6> table = [] {
        std::array<GpuModelHooks, 6> t = {smooth_gpu_hooks(),       deliot2023_gpu_hooks(),
                                          zirr2016_gpu_hooks(),     chermain2020_gpu_hooks(),
                                          kneiphof2025_gpu_hooks(), wang2020_gpu_hooks()};
        std::sort(t.begin(), t.end(), [](const GpuModelHooks& a, const GpuModelHooks& b) {
            return static_cast<int>(a.model) < static_cast<int>(b.model);
        });
        return t;
    }();
    return table;
}

const GpuModelHooks* find_gpu_model_hooks(GlintModelId model) {
    for (const GpuModelHooks& h : gpu_model_hooks())
        if (h.model == model) return &h;
    return nullptr;
}

}  // namespace glintlab
