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

void reset_model_params(GlintDesc& desc, GlintModelId model) {
    const GlintModelInfo* info = find_glint_model(model);
    if (info == nullptr) fail("unknown glint model id {}", static_cast<int>(model));
    desc.model_id = model;
    switch (model) {
        case GlintModelId::Deliot2023:
            desc.params = Deliot2023Params{};
            break;
        case GlintModelId::Zirr2016:
            desc.params = Zirr2016Params{};
            break;
        case GlintModelId::Chermain2020:
            // 004 §4.3: the multiscale SDF is separable only for Beckmann
            // (the scene loader rejects chermain2020 with GGX).
            desc.ndf = NdfType::Beckmann;
            desc.params = Chermain2020Params{};
            break;
        case GlintModelId::Wang2020:
            desc.base_albedo = glm::vec3(0.0f);  // it shades its lights itself: no base
            // the wang2020 descriptor's check: isotropic Beckmann, alpha in
            // [0.02, 1] (the DPF roughness set, 001 §4.4), ln N <= 19.4.
            desc.ndf = NdfType::Beckmann;
            desc.alpha_x = desc.alpha_y = std::clamp(desc.alpha_x, 0.02f, 1.0f);
            desc.log_density = std::clamp(desc.log_density, 0.0f, 19.4f);
            desc.params = Wang2020Params{};
            break;
        case GlintModelId::Kneiphof2025:
            desc.base_albedo = glm::vec3(0.0f);  // it shades its lights itself: no base
            // 003 §7-8: the split-sum tables are isotropic GGX with alpha <= 1
            // (the kneiphof2025 descriptor's check rejects anything else).
            desc.ndf = NdfType::GGX;
            desc.alpha_x = desc.alpha_y = std::min(desc.alpha_x, 1.0f);
            desc.params = Kneiphof2025Params{};
            break;
        default:
            desc.params = SmoothParams{};
            break;
    }
}

}  // namespace glintlab::gl
