// The OpenGL 4.5 forward renderer (ARCHITECTURE.md "realtime/"): draws the JSON scenes
// of the CPU renderer (meshes, analytic spheres tessellated with the CPU's uv
// parameterisation, camera, point/directional/sphere lights, environment
// background) with every material, glints through each model's shared .glsl
// (realtime/glint_programs.h). Output: linear radiance in an RGBA32F
// framebuffer, read back as a glintlab::Image (row 0 at the top), so the EXR,
// PNG (exposure) and bloom of the CPU path apply unchanged.
//
// Differences from the CPU `direct` integrator, by design of a forward
// shader (docs/ARCHITECTURE.md "realtime/"): shadow maps instead of shadow
// rays (directional, point and sphere lights; sphere lights cast the hard
// shadow of their centre); sphere lights are shaded as point lights of
// intensity pi r^2 L at their centre (exact for the irradiance of a fully
// visible sphere); cone (sun) lights at their axis; the environment lights
// surfaces through a deterministic filtered-importance-sampling estimate
// (forward_shaders.h) without occlusion; the dielectric shows its
// reflection only. kneiphof2025 materials shade the environment (Eq. 17 over
// prefiltered maps), sphere lights and sun cones themselves, as the CPU does
// at the first hit (glints/kneiphof2025/kneiphof2025_gpu.h). wang2020 materials with
// "blur" on defer their environment glints to a second colour attachment,
// blurred by the §4.4 passes and added into the colour target after the
// forward pass (as render_scene's postprocess_glints), with visibility 1:
// no directional-occlusion ray here.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "glintlab/core/image.h"
#include "glintlab/scene/scene.h"

namespace glintlab {

struct GpuPassTimes {
    double shadow_ms = 0.0;      // depth maps of the directional lights
    double background_ms = 0.0;  // environment / clear pass
    double forward_ms = 0.0;     // geometry + shading (the glint evaluation)
    // A glint model's post pass over the glint layer (wang2020's §4.4
    // blurs; 0: none this frame), GpuModelState::post_pass.
    double glint_post_ms = 0.0;
};

class GpuRenderer {
  public:
    // Needs a current OpenGL 4.5 core context (HeadlessContext or a GLFW
    // window). Uploads the shapes and the environment of `scene` and compiles
    // the programs it needs; throws glintlab::Error (with the shader log
    // mapped to file:line) when a program does not compile.
    explicit GpuRenderer(const Scene& scene);
    ~GpuRenderer();
    GpuRenderer(const GpuRenderer&) = delete;
    GpuRenderer& operator=(const GpuRenderer&) = delete;

    // Renders `scene` at its camera resolution. Camera, materials (including
    // the glint model) and light parameters may change between calls; the
    // shapes and the environment are those given to the constructor.
    void render(const Scene& scene);

    // The last frame: linear RGB, top row first.
    Image read_image() const;
    // Fragments of the last frame whose shading loops the OpenGL
    // implementation cut short (Mesa llvmpipe's loop limit,
    // forward.frag.glsl): 0 on a correct frame. Waits for the frame.
    uint64_t cut_fragments() const;
    unsigned hdr_texture() const;  // GL name of the RGBA32F colour attachment
    int width() const;
    int height() const;

    // Waits until the GPU has finished every command issued (glFinish).
    void finish() const;

    // GPU time of each pass of the last render() (waits for the queries).
    GpuPassTimes pass_times();

    // Environment radiance scale and rotation about +y (viewer controls);
    // initially those of the scene's map.
    void set_environment(float scale, float rotation_deg);
    bool has_environment() const;
    // A boolean GPU option of a glint model, off by default: `model` is a
    // registry name, `option` one of that model's GpuModelOption names
    // (glints/gpu_model_hooks.h; today deliot2023 "noise_texture", the
    // 000 §6.3 noise-texture variant, and kneiphof2025
    // "dynamic_environment", 003 §5's per-frame GPU prefilter). It applies to
    // every material of the model from the next render(). Throws
    // glintlab::Error naming the model, the option and the allowed ones.
    void set_model_option(std::string_view model, std::string_view option, bool on);
    bool model_option(std::string_view model, std::string_view option) const;
    // Shadow maps (on by default).
    void set_shadows(bool on);

    // Compiles (once) the program of every glint model the GPU supports with
    // the light set of `scene`, in every glue variant of the model's options.
    void compile_all_models(const Scene& scene);

  private:
    struct Impl;
    static std::unique_ptr<Impl> make_impl(const Scene& scene);
    std::unique_ptr<Impl> impl_;
};

// The warning for `cut` fragments of cut_fragments() ("" for 0).
std::string cut_fragments_warning(uint64_t cut);

// Renders `scene` headless (EGL) and returns the linear image: the GPU
// counterpart of render_scene(). The frame's cut_fragments go to
// *cut_fragments, or without it cut_fragments_warning to stderr.
Image render_scene_gpu(const Scene& scene, uint64_t* cut_fragments = nullptr);

}  // namespace glintlab
