// Scene integration of wang2020 (registry row "wang2020"): parameter block
// reading and the GlintModelInfo::shades_light / light_radiance hooks
// (glint_lighting.h). The model shades the camera's first hit for
// environment, point and directional lights itself (Eqs. 18–21); the tables
// (DPF set, extracted DPF, prefiltered environment, quadtree) are built lazily
// once per (material parameters, environment map) and cached, thread-safe.
// In renders with "blur" on, the environment term goes through
// GlintPostSample to the §4.4 blurs (wang2020_postprocess.h), which
// render_scene (and GpuRenderer, glints/wang2020/wang2020_gpu_blur.h) run on the
// image; see docs/MODELS.md.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

namespace glintlab {

namespace wang2020 {
class Wang2020Model;
}
class EnvironmentMap;
struct GlintDesc;
struct GlintLightingContext;
struct Scene;

// N of a material (its GlintDesc::log_density): round(e^log_density) particles per uv tile (the
// explicit ground truth's convention); the quadtree holds N, the scene reader checks `depth`
// against it (check_wang2020, wang2020_quadtree.h's bounds). Inline: the scene reader's check needs
// it in the fuzzing build's loaders.
inline uint64_t wang2020_particles(float log_density) {
    return static_cast<uint64_t>(std::llround(std::exp(static_cast<double>(log_density))));
}

bool wang2020_shades_light(const GlintDesc& desc, const Scene& scene, int light);
glm::vec3 wang2020_light_radiance(const GlintLightingContext& ctx, int light);

// The glint kernel of 001 §4.4's post-process for a scene's image: 3 taps
// when its shapes' wang2020 materials with "blur" on have "glint_blur":
// "as_published", or "auto" and the image has one sample per pixel
// (one_sample: the GPU, a CPU render at 1 spp); else 1 (no glint blur; the
// 9-tap occlusion blur still runs). One post-process runs per image
// (render_scene, GpuRenderer), so materials that resolve to different
// kernels are an error naming both.
int wang2020_glint_blur_taps(const Scene& scene, bool one_sample);

// The cached tables of a wang2020 material (built on first use): the ones
// the CPU renderer shades with, so the GPU renderer uploads the same arrays.
// `env` may be null (no prefiltered tables: point and directional lights only).
std::shared_ptr<const wang2020::Wang2020Model> wang2020_model_for(
    const GlintDesc& desc, const std::shared_ptr<const EnvironmentMap>& env);

}  // namespace glintlab
