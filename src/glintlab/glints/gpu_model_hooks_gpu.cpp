// The GPU models (gpu_model_hooks.h), gathered from the model descriptors:
// each names its own hooks (GlintModelDescriptor::gpu_hooks), so this file
// names no model. Built with the OpenGL renderer only (GLINTLAB_WITH_GL).
#include <set>
#include <vector>

#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/glints/gpu_model_hooks.h"
#include "glintlab/glints/registry.h"
#include "glintlab/scene/scene.h"

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

GpuModelOptionName find_scene_gpu_option(const Scene& scene, std::string_view name) {
    const size_t dot = name.find('.');
    const std::string_view model = dot == std::string_view::npos ? "" : name.substr(0, dot);
    const std::string_view option = dot == std::string_view::npos ? name : name.substr(dot + 1);
    std::set<GlintModelId> used;  // the scene's GPU models, in registry order
    for (const MaterialDesc& m : scene.materials)
        if (m.type == MaterialDesc::Type::Glint && find_gpu_model_hooks(m.glint.model_id))
            used.insert(m.glint.model_id);
    std::vector<GpuModelOptionName> matches;
    std::string known;
    for (GlintModelId id : used) {
        const std::string_view model_name = glint_model(id).name;
        for (const GpuModelOption& o : find_gpu_model_hooks(id)->options) {
            known += fmt::format("{}{}.{}", known.empty() ? "" : ", ", model_name, o.name);
            if (o.name == option && (model.empty() || model == model_name))
                matches.push_back({model_name, o.name});
        }
    }
    if (matches.size() == 1) return matches.front();
    fail("GPU option \"{}\": {} (the GPU options of this scene's glint models: {})", name,
         matches.empty() ? "no glint model of this scene has it"
                         : "several of this scene's models have it; name one as MODEL.OPTION",
         known.empty() ? "none" : known);
}

}  // namespace glintlab
