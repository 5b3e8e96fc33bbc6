// The GPU host side of a glint model, as the OpenGL renderer
// (realtime/gpu_renderer.h) sees it: one GpuModelHooks per model, implemented
// beside the model (glints/<model>/<model>_gpu*.cpp) and named by its
// descriptor (GlintModelDescriptor::gpu_hooks); gpu_model_hooks() gathers
// them (glints/gpu_model_hooks_gpu.cpp). The renderer never names a model: it
// asks for the model's GLSL glue file, makes the model's per-renderer state
// and calls it before each frame and before each draw of one of the model's
// materials.
//
// This header needs no OpenGL; the hooks' implementations (*_gpu*.cpp) are
// built with GLINTLAB_WITH_GL only, and so is gpu_model_hooks().
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "glintlab/glints/registry.h"

namespace glintlab {

struct GlintDesc;
struct Scene;

namespace gl {
class UniformCache;
}

// Texture units 0..3 are the forward shader's (realtime/forward_shaders.h);
// models use units 4-9 (chermain2020 4, deliot2023 5, kneiphof2025 6-9); textured
// material parameters take 10-15 (forward_shaders.h kMaterialTextureUnit).
inline constexpr int kFirstModelTextureUnit = 4;

// One boolean GPU option of a model (GpuRenderer::set_model_option, a viewer
// checkbox, a bench flag), off by default. The renderer keeps one mask per
// model: bit i is options[i].
struct GpuModelOption {
    std::string_view name;         // "noise_texture"
    std::string_view description;  // one line, for error messages and UIs
    bool changes_program;          // selects another glue variant (part of the program key)
};

// What the renderer tells a model's hooks about the current frame.
struct GpuFrame {
    const Scene& scene;
    unsigned environment_texture = 0;  // GL name of the lat-long RGB32F map (0: none)
    int environment_width = 0, environment_height = 0;
    float environment_scale = 1.0f;         // viewer control, initially the map's
    float environment_rotation_rad = 0.0f;  // about +y, likewise
};

// The GPU resources of one model in one renderer (textures, buffers, cached
// tables): made on first use, in the renderer's context, freed with it.
class GpuModelState {
  public:
    virtual ~GpuModelState() = default;
    // Once per frame, before any pass, when the scene has a material of the
    // model (may run compute passes and rebind any unit).
    virtual void begin_frame(const GpuFrame& frame, unsigned options);
    // Before each draw of a material `desc` of the model with `program`:
    // binds the model's resources and sets its uniforms.
    virtual void prepare(unsigned program, gl::UniformCache& uniforms, const GlintDesc& desc,
                         const GpuFrame& frame, unsigned options) = 0;
    // After the forward pass of a frame in which a material of the model
    // wrote the glint layer (GpuModelHooks::uses_glint_layer): combines the
    // layer (RGBA32F: rgb glints, a visibility; width x height) into the
    // colour target `color` (RGBA32F).
    virtual void post_pass(unsigned glint_layer, unsigned color, int width, int height);
};

struct GpuModelHooks {
    GlintModelId model = GlintModelId::Smooth;
    // Embedded path of the GLSL glue file (glints/<model>/<model>_gpu.glsl)
    // for the mask of the options that change the program.
    std::string (*glue_path)(unsigned program_options) = nullptr;
    std::span<const GpuModelOption> options;
    // Null: the model has neither resources nor uniforms of its own.
    std::unique_ptr<GpuModelState> (*make_state)() = nullptr;
    // Whether the forward pass writes the environment glints of `desc` to
    // the glint layer (colour attachment 1, forward.frag.glsl u_glint_layer
    // on; cleared to (0, 0, 0, 1)) instead of the colour target, for the
    // state's post_pass; null: never. One model per frame may use it.
    bool (*uses_glint_layer)(const GlintDesc& desc) = nullptr;

    // Bits of `options` that select a glue variant.
    unsigned program_option_mask() const;
    // Index of the option called `name`, or -1.
    int option_index(std::string_view name) const;
};

// Every model the GPU renderer implements, in registry order.
std::span<const GpuModelHooks> gpu_model_hooks();
// Null when the GPU renderer does not implement `model`.
const GpuModelHooks* find_gpu_model_hooks(GlintModelId model);

// A GPU option of a model, by name: "OPTION" or "MODEL.OPTION".
struct GpuModelOptionName {
    std::string_view model;   // the model's registry name
    std::string_view option;  // GpuModelOption::name
};
// The option `name` of a model that a glint material of `scene` uses
// (`glintlab view --gpu-option`); a bare OPTION must belong to one such
// model only. Throws glintlab::Error naming the options the scene's models
// have otherwise.
GpuModelOptionName find_scene_gpu_option(const Scene& scene, std::string_view name);

}  // namespace glintlab
