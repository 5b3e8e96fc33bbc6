// kneiphof2025's environment prefilter as OpenGL compute passes (003 §5,
// "dynamic IBL": redone every frame), the GPU counterpart of
// Kneiphof2025Environment (glints/kneiphof2025/kneiphof2025_prefilter.h)
// with the same options, layout and algorithm:
//   1. base level: the radiance resampled to W x H (ss x ss bilinear source
//      samples per texel), its luminance, and the luminance range (atomic
//      min / max on the float bits; luminance >= 0);
//   2. the K radiance levels (Eq. 18) from that range, on the host (two
//      floats read back; kneiphof2025_radiance_levels, the CPU's function);
//   3. the fuzzy partition of every texel (Eq. 19, kneiphof2025_partition.glsl);
//   4. the box pyramid (2 x 2 averages down to 2 x 1) of the RGB and K weight
//      channels;
//   5. the split-sum GGX prefilter of every channel with one kernel (Eq. 11,
//      20-21; kneiphof2025_prefilter_kernel, the CPU's samples and LODs),
//      read from the pyramid by trilinear lookups, into layers 1 .. M-1 of
//      three lat-long texture arrays (RGB radiance, weights 1-4, weights 5-8);
//      layer 0 is the base level (the mirror).
//   6. (Reduced resolution only) the layers filtered below W x H upsampled
//      bilinearly to W x H.
// The arrays are what kneiphof2025.glsl's GLSL fetch functions read.
//
// Resolution of pass 5. Full: every layer filtered at W x H, the CPU's
// values (up to fp32 rounding). Reduced (the renderer's dynamic default):
// layer m is filtered on the 2^-s_m coarser grid, s_m = floor of
// the smallest LOD of its kernel's samples (at most 2, and so that the grid
// keeps >= 4 rows), and upsampled bilinearly (u wraps, v clamps at texel
// centres: the sampling the forward shader itself does within a layer). Every sample of layer m
// reads pyramid levels >= s_m, i.e. data that is already box-filtered to
// 2^s_m base texels and interpolated bilinearly between them, so the
// filtered layer carries no detail finer than that grid and a bilinear
// reconstruction from it is of the same order as the pyramid's own. At the
// default 256 x 128 and 64 samples s = 0, 1, 2, 2, 2, 2 for sqrt(alpha) =
// 1/6 .. 1 (the smallest LODs are 0, 1.34, 2.51, 3.34, 3.98, 4.50): the
// sharpest layer (whose kernel reads level 0) stays exact and pass 5 does
// 1.5 instead of 6 full-resolution layers of kernel lookups. The result is
// not the CPU's to rounding: each of the 64 samples reads its pyramid level
// bilinearly, so the full-resolution layer has slope breaks at that level's
// texel edges (part of the estimator's own error), which the coarse grid
// does not reproduce. Measured on the 8 Blender studio lights
// (docs/BENCHMARKS.md): mean difference to the CPU layers <= 0.6 %
// of a channel's range, single texels next to small bright sources up to
// 32 %; against the kernel integral itself (Kneiphof et al. 2025, Eq. 11,
// 21, summed over every base texel) the reduced layers are as close as the full-resolution ones.
// With K = 4 the lookups of weights 5-8 (all zero) are skipped in both
// modes.
#pragma once

#include <array>
#include <vector>

#include "glintlab/gl/gl_handles.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"

namespace glintlab::gl {

// An RGBA32F lat-long texture array in the layout kneiphof2025.glsl reads:
// layer i holds sqrt(alpha) = i / (layers - 1); bilinear within a layer (u
// wraps, v clamps at texel centres, as the CPU's bilinear()); the shader
// blends the two layers around the roughness itself. Used for the static
// (uploaded) and the dynamic (compute-prefiltered) maps alike.
Texture make_latlong_array(int width, int height, int layers);

class Kneiphof2025GpuPrefilter {
  public:
    // Compiles the passes and allocates the textures (needs a current GL 4.5
    // context). Throws glintlab::Error for out-of-range options (the CPU's
    // ranges).
    enum class Resolution { Full, Reduced };
    explicit Kneiphof2025GpuPrefilter(const Kneiphof2025PrefilterOptions& options,
                                      Resolution resolution = Resolution::Full);
    ~Kneiphof2025GpuPrefilter();
    Kneiphof2025GpuPrefilter(const Kneiphof2025GpuPrefilter&) = delete;
    Kneiphof2025GpuPrefilter& operator=(const Kneiphof2025GpuPrefilter&) = delete;

    // Prefilters `source` (a lat-long RGB(A) float texture in the
    // EnvironmentMap convention, read at level 0 with GL_REPEAT in u and
    // GL_CLAMP_TO_EDGE in v, bilinear) of source_width x source_height
    // texels, radiance = texel x scale. Reads back the luminance range (a
    // sync point: 8 bytes).
    void run(unsigned source, int source_width, int source_height, float scale);

    int levels() const { return options_.levels; }
    int layers() const { return options_.mip_count; }
    Resolution resolution() const { return resolution_; }
    // s_m of the header: layer m is filtered at (W >> s_m) x (H >> s_m)
    // (0 for every layer at Resolution::Full and for layer 0).
    int filter_shift(int layer) const { return shift_.at(static_cast<size_t>(layer)); }
    // L^(k) of the last run (Eq. 18).
    const std::array<float, 8>& radiance_levels() const { return radiance_levels_; }
    unsigned radiance() const { return radiance_.get(); }
    unsigned weights_a() const { return weights_a_.get(); }
    unsigned weights_b() const { return weights_b_.get(); }
    // One layer read back in the CPU's interleaved layout (3 + K channels).
    Kneiphof2025Level read_layer(int layer) const;

  private:
    Kneiphof2025PrefilterOptions options_;
    Resolution resolution_;
    int width_, height_, pyramid_levels_, coarse_levels_;
    std::array<float, 8> radiance_levels_{};
    Program base_, partition_, reduce_, filter_, upsample_;
    Buffer range_;                                  // 2 uints: min, max luminance bits
    Buffer kernels_;                                // every layer's kernel (pass 5)
    std::vector<int> kernel_first_, kernel_count_;  // per layer, in samples
    std::vector<int> shift_;                        // per layer: s_m
    Texture pyramid_[3];                            // RGB + luminance, weights 1-4, weights 5-8
    Texture radiance_, weights_a_, weights_b_;      // the output arrays
    Texture coarse_[3];  // Reduced: layer m at mip level s_m (same 3 channel groups)
};

}  // namespace glintlab::gl
