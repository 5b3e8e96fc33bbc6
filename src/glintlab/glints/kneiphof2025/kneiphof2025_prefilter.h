// CPU prefiltering for kneiphof2025 (Kneiphof & Klein 2025, 003 §3.4, §5): the K radiance
// levels of an environment (Eq. 18), its fuzzy indicator maps (Eq. 19), and
// the split-sum GGX prefiltering of the radiance and of the K indicator maps
// with the same kernel (Eq. 11, 20-21), plus the DFG / E_D lookup table.
//
// Resolutions (docs/MODELS.md "kneiphof2025"):
// - Maps are lat-long in the EnvironmentMap's own (u, v) convention, so a
//   lookup is env.direction_to_uv(dir) (the map's rotation included).
// - M = 7 levels, level i holding roughness sqrt(alpha) = i / (M - 1), all
//   at 256 x 128 (1.4 deg texels; a texture array on a GPU). Level 0 is the
//   environment box-filtered to that size, unfiltered: the mirror. A halving
//   mip chain (8 x 4 at sqrt(alpha) = 1) was tried first: its bilinear lookups
//   at 22-45 deg texels smear the horizon, and the mean radiance was 10-30 %
//   off on the validation sphere; 256 x 128 is the coarsest size at which the
//   filtered radiance matched a brute-force kernel integral to a few percent
//   at every level (the smallest filtered lobe, sqrt(alpha) = 1/6, is 3.2 deg
//   wide). Lookups blend the two nearest levels linearly in sqrt(alpha).
// - Each filtered texel is a 64-sample Hammersley estimate of the GGX
//   kernel p(wi) ~ D(h) <n, wi> with n = v = r (Karis 2013), each sample read
//   from a box-filtered source pyramid at the LOD that matches its solid
//   angle (filtered importance sampling), so 64 samples show no noise.
// - DFG LUT: 32 x 32 over (cos_o, sqrt(alpha)) at texel centres, 2048
//   Hammersley samples per entry: A, B (E_rho = F0 A + B for Schlick's F
//   with the height-correlated Smith G2) and E_D / D_H (Eq. 21, 8).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

namespace glintlab {

class ByteReader;
class ByteWriter;
class EnvironmentMap;
class ProgressReporter;

struct Kneiphof2025PrefilterOptions {
    int levels = 8;             // K in {4, 8}
    float black_level = 1e-2f;  // l: the dimmest non-zero level is max(min L, l), 003 §5
    int base_width = 256;       // width of every level (height = width / 2); a power of two >= 16
    int mip_count = 7;  // levels incl. the mirror; level i has roughness i / (mip_count - 1)
    int samples = 64;   // kernel samples per filtered texel
};

// The environment's bright sources (a sun, a studio's lamps, a window),
// taken out of the prefiltered radiance for the "lobe_sun" smooth term and
// shaded as kSamples directions inside them (docs/MODELS.md "kneiphof2025",
// smooth term): split_environment_sources (scene/environment_sources.h) of
// the 256 x 128 base level. A lobe's few dozen samples reading GGX-blurred
// levels weight a lamp in the lobe's tail as if it sat where the lobe is
// strong (blender's studio on a plane at grazing view: 4x the image).
struct Kneiphof2025Sources {
    static constexpr int kSamples = 16;  // kneiphof2025.glsl KNEIPHOF2025_SOURCES
    // A source's texels: luminance >= 10 x the map's mean (its halo too;
    // the split's default, max(5 % of the peak, 50 x mean), left +21 % on
    // the studio plane at alpha 0.09; 10 x: +9 %).
    static constexpr float kTexelContrast = 10.0f;
    std::vector<glm::vec3> directions;      // world (the map's rotation applied), unit
    std::vector<glm::vec3> map_directions;  // in the map's own frame (rotation 0)
    std::vector<glm::vec3> powers;          // RGB: radiance above the surroundings x solid angle
    std::vector<float> radii;               // angular radius (rad) each direction stands for
    glm::vec3 color{0.0f};  // sum of powers / its luminance: the sources channel's colour
    bool empty() const { return directions.empty(); }
};

// The world direction of a direction in the map's own frame: the map's
// rotation about +y (map_uv: world phi = map phi + rotation); unit.
glm::vec3 kneiphof2025_map_to_world(glm::vec3 d, float rotation_rad);

// One lat-long level: channels per texel = 3 (RGB radiance) + K (weights).
struct Kneiphof2025Level {
    int width = 0, height = 0;
    std::vector<float> data;
};

class Kneiphof2025Environment {
  public:
    // Partitions and prefilters `env` (radiance = image x scale). Throws
    // glintlab::Error for out-of-range options. With a progress reporter,
    // one update per row of each level (mip_count x base_width / 2 in all).
    Kneiphof2025Environment(const EnvironmentMap& env, const Kneiphof2025PrefilterOptions& options,
                            ProgressReporter* progress = nullptr);

    // The constructor through the on-disk table cache (core/disk_cache.h,
    // file kCacheName-<key>.bin): a hit is the constructed environment bit
    // for bit; otherwise it is built with a progress bar (on a terminal) and
    // stored. *from_cache (if given) tells which. kneiphof2025_environment_for
    // builds its maps this way.
    static constexpr const char* kCacheName = "kneiphof2025_prefilter";
    static std::shared_ptr<const Kneiphof2025Environment> load_or_build(
        const EnvironmentMap& env, const Kneiphof2025PrefilterOptions& options,
        bool* from_cache = nullptr);
    // The key of every input the maps depend on: the image's size and
    // pixels, the map's scale (applied before the prefilter), every
    // Kneiphof2025PrefilterOptions field, the sources' constants and a table
    // version. Not the rotation: the maps are in the map's own frame, the
    // rotation enters at lookup (and in sources().directions, set on load).
    static uint64_t cache_key(const EnvironmentMap& env,
                              const Kneiphof2025PrefilterOptions& options);

    int levels() const { return levels_; }
    int channels() const { return 3 + levels_; }
    // L^(k), k = 0 .. K-1 (003's k = 1 .. K); L^(0) = 0 (Eq. 18).
    const std::array<float, 8>& radiance_levels() const { return radiance_levels_; }
    float min_luminance() const { return min_luminance_; }
    float max_luminance() const { return max_luminance_; }
    const std::vector<Kneiphof2025Level>& mips() const { return mips_; }

    // Prefiltered channels at a world direction and roughness sqrt(alpha) in
    // [0, 1]: out[0..2] RGB radiance, out[3 .. 3+K) the weights (not
    // renormalised). Bilinear within a level, linear between levels.
    void fetch(glm::vec3 dir, float roughness, float* out) const;
    // The RGB radiance alone (out[0..2] of fetch).
    glm::vec3 fetch_radiance(glm::vec3 dir, float roughness) const;
    // The RGB radiance and, in w, the sources' luminance in it (their
    // radiance above their surroundings alone, prefiltered by the same
    // kernel; 0 without sources).
    glm::vec4 fetch_radiance_sources(glm::vec3 dir, float roughness) const;
    const Kneiphof2025Sources& sources() const { return sources_; }
    // The sources channel of each level (one float per texel, same layout).
    const std::vector<Kneiphof2025Level>& source_mips() const { return source_mips_; }

    // Fuzzy indicator weights of Eq. 19 for a luminance (linear space),
    // into w[0 .. K).
    void partition(float luminance, float* w) const;

  private:
    Kneiphof2025Environment() = default;  // load_or_build's, filled by read()
    // The payload of the cache file (a versioned layout, kneiphof2025_prefilter.cpp).
    void write(ByteWriter& out) const;
    // False (and *this unusable) for a payload whose layout, version or
    // sizes do not match what `options` imply.
    bool read(ByteReader& in, const Kneiphof2025PrefilterOptions& options, float rotation_deg);
    void fetch_channels(glm::vec3 dir, float roughness, float* out, int count) const;
    // Sets sources_ from the base level's radiance and writes each texel's
    // luminance above the residual into the last of `stride` channels of `base`.
    void find_sources(int W, int H, std::vector<float>& base, int stride);
    void fetch_level(int level, glm::vec2 uv, float* out, int count) const;

    float rotation_rad_ = 0.0f;
    int levels_ = 0;
    std::array<float, 8> radiance_levels_{};
    float min_luminance_ = 0.0f, max_luminance_ = 0.0f;
    std::vector<Kneiphof2025Level> mips_;
    Kneiphof2025Sources sources_;
    std::vector<Kneiphof2025Level> source_mips_;
};

// Eq. 18: the K radiance levels (L^(1) = 0, then log-spaced from
// max(min luminance, black level) to the max luminance), entries >= K zero.
std::array<float, 8> kneiphof2025_radiance_levels(float min_luminance, float max_luminance,
                                                  int levels, float black_level);

// One sample of the split-sum prefilter kernel (Eq. 11, 21) in the frame of
// n = v = r (z up): direction, weight <n, wi>, and the LOD in the box
// pyramid of a width x height lat-long level whose texels match the
// sample's solid angle.
struct Kneiphof2025KernelSample {
    glm::vec3 l;
    float weight, lod;
};
// The kernel of the level of roughness sqrt(alpha) (the CPU prefilter's and
// the GPU's per-frame prefilter's).
std::vector<Kneiphof2025KernelSample> kneiphof2025_prefilter_kernel(float roughness, int samples,
                                                                    int width, int height);

// The split-sum tables of isotropic GGX (built once, thread-safe).
class Kneiphof2025DfgLut {
  public:
    static constexpr int kSize = 32;
    static constexpr int kSamples = 2048;
    static const Kneiphof2025DfgLut& get();
    // (A, B, E_D / D_H), bilinear over texel centres, clamped at the borders.
    glm::vec3 lookup(float cos_o, float roughness) const;
    // The table as a kSize x kSize RGBA float texture, (A, B, E_D / D_H, 0)
    // looked up at the texel centres (x: cos_o, y: sqrt(alpha)): the GPU
    // renderer's texture and the export's resource.
    std::vector<float> rgba_texture() const;
    // One entry computed directly (the table's integrand), for tests.
    static glm::vec3 integrate(float cos_o, float roughness, int samples);
    // The whole table (row-major over (roughness, cos_o)), computed; with a
    // progress reporter, one update per row.
    static std::vector<glm::vec3> compute_table(ProgressReporter* progress = nullptr);
    // compute_table through the on-disk table cache (core/disk_cache.h),
    // keyed by kSize, kSamples and a table version: a hit is the computed
    // table bit for bit; otherwise it is computed with a progress bar (on a
    // terminal) and stored. get() builds its table this way.
    static std::vector<glm::vec3> load_or_compute_table();
    static uint64_t cache_key();

  private:
    Kneiphof2025DfgLut();
    std::vector<glm::vec3> table_;
};

// D_H: total facet area of isotropic GGX (003 §3.2), closed form
// (kneiphof2025.glsl kneiphof2025_total_facet_area).
float kneiphof2025_total_facet_area(float alpha);

// The prefiltered environment of `env` for (K, black level), built on first
// use (through the on-disk cache, Kneiphof2025Environment::load_or_build) and
// kept per EnvironmentMap (thread-safe; an entry whose map has been
// destroyed is rebuilt for a new map at the same address).
std::shared_ptr<const Kneiphof2025Environment> kneiphof2025_environment_for(
    const std::shared_ptr<const EnvironmentMap>& env, int levels, float black_level);

}  // namespace glintlab
