#include "glintlab/realtime/glint_programs.h"

#include <algorithm>
#include <variant>

#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/scene/scene.h"

namespace glintlab::gl {

bool gpu_supports_model(GlintModelId model) {
    return find_gpu_model_hooks(model) != nullptr;
}

std::string glint_model_glue_path(GlintModelId model, unsigned program_options) {
    if (const GpuModelHooks* hooks = find_gpu_model_hooks(model))
        return hooks->glue_path(program_options);
    std::string supported;
    for (const GpuModelHooks& h : gpu_model_hooks()) {
        const GlintModelInfo* info = find_glint_model(h.model);
        supported += fmt::format("{}{}", supported.empty() ? "" : ", ", info ? info->name : "?");
    }
    const GlintModelInfo* info = find_glint_model(model);
    fail("OpenGL renderer: glint model \"{}\" has no GPU implementation (GPU models: {})",
         info != nullptr ? info->name : "?", supported);
}

std::string glint_model_glsl(GlintModelId model, unsigned program_options) {
    return fmt::format("#include \"{}\"\n", glint_model_glue_path(model, program_options));
}

}  // namespace glintlab::gl
