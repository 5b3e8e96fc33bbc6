// wang2020 (Wang et al. 2020, 001) in the OpenGL renderer: the GLSL glue
// (glints/wang2020/wang2020_gpu.glsl) over the shared wang2020_tables.glsl
// and the three table buffers it reads. The tables are
// the CPU renderer's own (wang2020_model_for: the same DPF extraction,
// prefiltered environment and quadtree, built by the CPU code and uploaded
// unchanged as SSBOs), so CPU and GPU shade from identical data.
//
// The model lights the camera's first hit itself (glint_lighting.h): the
// glue defines GLINTLAB_GLINT_OWN_LIGHTS and
//     vec3 glint_own_light_add(vec3 wo, vec3 wi, vec3 li, Footprint fp);  // Eq. 21, batched
//     vec3 glint_own_lights_flush(vec3 wo, Footprint fp);                 // the batch's rest
//     vec3 glint_own_environment(vec3 n, vec3 o_world, Footprint fp);  // Eqs. 18-20
// which realtime/shaders/forward.frag.glsl calls instead of the BRDF for glint materials
// (both before the material tint). Directional occlusion (§4.4) of the
// environment has no ray tracer here and is left out (docs/MODELS.md).
#pragma once

#include <memory>
#include <string>

#include "glintlab/gl/gl_handles.h"

namespace glintlab {

struct GlintDesc;
struct Scene;
namespace wang2020 {
class Wang2020Model;
}

namespace gl {

class UniformCache;

// SSBO bindings of the tables (binding 0 is the forward shader's triangles).
inline constexpr int kWang2020DpfBinding = 1;
inline constexpr int kWang2020PrefilterBinding = 2;
inline constexpr int kWang2020NodeBinding = 3;
inline constexpr int kWang2020ConeBinding = 4;  // L_γ ("micro": "per_particle")

class Wang2020Resources {
  public:
    // Builds (first use, cached by the CPU code) and uploads the tables of
    // `desc` under the scene's environment (the first environment light, if
    // any), binds them and sets the model's uniforms of `program`.
    void bind(unsigned program, UniformCache& uniforms, const GlintDesc& desc, const Scene& scene);
    // The model last bound (for benchmarks and tests).
    const wang2020::Wang2020Model* model() const { return model_.get(); }

  private:
    std::shared_ptr<const wang2020::Wang2020Model> model_;
    Buffer dpf_, prefilter_, nodes_, cone_;
};

}  // namespace gl
}  // namespace glintlab
