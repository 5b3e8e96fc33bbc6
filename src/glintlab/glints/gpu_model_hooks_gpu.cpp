// The GPU models (gpu_model_hooks.h), gathered from the model descriptors:
// each names its own hooks (GlintModelDescriptor::gpu_hooks), so this file
// names no model. Built with the OpenGL renderer only (GLINTLAB_WITH_GL).
#include <vector>

#include "glintlab/core/error.h"
#include "glintlab/glints/gpu_model_hooks.h"
#include "glintlab/glints/registry.h"

namespace glintlab {

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
    static const std::vector<GpuModelHooks> table = [] {
        std::vector<GpuModelHooks> t;
        for (const GlintModelDescriptor& m : glint_models()) {
            if (m.gpu != (m.gpu_hooks != nullptr))
                fail("internal error: glint model \"{}\" says gpu = {} but has {}GPU hooks", m.name,
                     m.gpu, m.gpu ? "no " : "");
            if (m.gpu_hooks == nullptr) continue;
            t.push_back(m.gpu_hooks());
            if (t.back().model != m.id)
                fail("internal error: the GPU hooks of glint model \"{}\" are another model's",
                     m.name);
        }
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
