// The GPU resources of the kneiphof2025 glint model (Kneiphof & Klein 2025, 003): the
// environment prefiltered on the CPU (kneiphof2025_prefilter.h: K radiance
// levels Eq. 18, fuzzy indicators Eq. 19, split-sum GGX prefilter Eq. 11,
// 20-21) uploaded as the texture arrays that kneiphof2025.glsl's GLSL fetch
// functions read, the DFG / E_D table (Eq. 11, 21), and the model's
// uniforms. Kept out of glints/ so that the model folder stays GL-free.
#pragma once

#include <map>
#include <memory>
#include <tuple>
#include <utility>

#include "glintlab/gl/gl_handles.h"

namespace glintlab {

class EnvironmentMap;
class Kneiphof2025Environment;
struct GlintDesc;
struct Scene;

namespace gl {

class UniformCache;
class Kneiphof2025GpuPrefilter;

// Texture units of the model (after the forward shader's 0-3 and the other
// models' 4-5; see glint_programs.h kFirstModelTextureUnit).
inline constexpr int kKneiphof2025RadianceUnit = 6;
inline constexpr int kKneiphof2025WeightsAUnit = 7;
inline constexpr int kKneiphof2025WeightsBUnit = 8;
inline constexpr int kKneiphof2025DfgUnit = 9;

class Kneiphof2025Resources {
  public:
    Kneiphof2025Resources();
    ~Kneiphof2025Resources();
    Kneiphof2025Resources(const Kneiphof2025Resources&) = delete;
    Kneiphof2025Resources& operator=(const Kneiphof2025Resources&) = delete;

    // Binds the textures of `desc` (a kneiphof2025 material) in `scene` and
    // sets the model's uniforms of `program`. The prefiltered environment is
    // built (CPU, cached per map) and uploaded on first use of each
    // (map, K, black level). `environment_scale` / `environment_rotation_rad`
    // are the renderer's current values (viewer controls): the maps were
    // prefiltered at the map's own scale, so the radiance is rescaled
    // (exact for the radiance; the partition keeps the black level of the
    // original scale) and read with the current rotation.
    void prepare(unsigned program, UniformCache& uniforms, const Scene& scene,
                 const GlintDesc& desc, float environment_scale, float environment_rotation_rad);

    // Dynamic IBL (003 §5, Table 1 "Dynamic IBL"): the maps are prefiltered
    // on the GPU (kneiphof2025_prefilter_gpu.h) in every frame instead of
    // once on the CPU. Off by default. full_resolution: every layer filtered
    // at full resolution (Kneiphof2025GpuPrefilter::Resolution::Full) rather
    // than the default Reduced grids.
    void set_dynamic(bool on, bool full_resolution = false) {
        dynamic_ = on;
        full_resolution_ = full_resolution;
    }
    bool dynamic() const { return dynamic_; }
    // Dynamic mode: runs the GPU prefilter of `environment` (the renderer's
    // lat-long texture, width x height texels, radiance = texel x scale) for
    // every (K, black level) of the scene's kneiphof2025 materials. Call once
    // per frame before drawing (it rebinds texture and image units 0-5).
    void begin_frame(const Scene& scene, unsigned environment, int width, int height, float scale);

  private:
    struct Maps {
        std::shared_ptr<const Kneiphof2025Environment> env;
        std::shared_ptr<const EnvironmentMap> owner;  // keeps the map's address unique
        Texture radiance, weights_a, weights_b;
    };
    const Maps& maps_for(const std::shared_ptr<const EnvironmentMap>& map, int levels,
                         float black_level);
    std::map<std::tuple<const EnvironmentMap*, int, float>, Maps> maps_;
    Texture dfg_;
    bool dynamic_ = false, full_resolution_ = false;
    // Per (K, black level, full resolution).
    std::map<std::tuple<int, float, bool>, std::unique_ptr<Kneiphof2025GpuPrefilter>>
        gpu_prefilters_;
};

}  // namespace gl
}  // namespace glintlab
