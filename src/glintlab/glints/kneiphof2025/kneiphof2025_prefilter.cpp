#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <glm/gtc/constants.hpp>

#include "glintlab/core/disk_cache.h"
#include "glintlab/core/error.h"
#include "glintlab/core/glsl.h"
#include "glintlab/core/image.h"
#include "glintlab/core/progress.h"
#include "glintlab/core/radical_inverse.h"
#include "glintlab/microfacet/microfacet.h"
#include "glintlab/scene/environment.h"
#include "glintlab/scene/environment_sources.h"

// Eq. 19, one source with the GPU's per-frame prefilter.
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/kneiphof2025/kneiphof2025_partition.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

constexpr float kPi = glm::pi<float>();

glm::vec2 hammersley(int i, int n) {
    return {(static_cast<float>(i) + 0.5f) / static_cast<float>(n),
            radical_inverse_f(static_cast<uint32_t>(i))};
}

// Half vector with density D(h) cos(theta_h) for isotropic GGX (local frame).
glm::vec3 sample_ggx_cos(float alpha, glm::vec2 u) {
    const float a2 = alpha * alpha;
    const float cos2 = (1.0f - u.x) / (1.0f + (a2 - 1.0f) * u.x);
    const float cos_t = std::sqrt(std::max(cos2, 0.0f));
    const float sin_t = std::sqrt(std::max(1.0f - cos2, 0.0f));
    const float phi = 2.0f * kPi * u.y;
    return {sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t};
}

float d_ggx(glm::vec3 h, float alpha) {
    return shader::D_Microfacet(shader::NDF_GGX, h, alpha, alpha);
}

// Lat-long in the map's own frame (rotation 0), the EnvironmentMap convention.
glm::vec3 map_direction(glm::vec2 uv) {
    const float theta = uv.y * kPi;
    const float phi = (uv.x - 0.5f) * 2.0f * kPi;
    const float s = std::sin(theta);
    return {s * std::sin(phi), std::cos(theta), -s * std::cos(phi)};
}

glm::vec2 map_uv(glm::vec3 d, float rotation_rad) {
    const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
    float u = 0.5f + (std::atan2(d.x, -d.z) - rotation_rad) / (2.0f * kPi);
    u -= std::floor(u);
    return {u, theta / kPi};
}

// Bilinear lookup of C channels in a lat-long level (u wraps, v clamps).
// `count` <= channels: the first `count` channels only (the radiance alone).
void bilinear(const Kneiphof2025Level& l, int channels, glm::vec2 uv, float* out, int count) {
    const float fx = uv.x * static_cast<float>(l.width) - 0.5f;
    const float fy = uv.y * static_cast<float>(l.height) - 0.5f;
    const float x0f = std::floor(fx), y0f = std::floor(fy);
    const float tx = fx - x0f, ty = fy - y0f;
    const int x0 = static_cast<int>(x0f), y0 = static_cast<int>(y0f);
    const int xa = ((x0 % l.width) + l.width) % l.width, xb = (xa + 1) % l.width;
    const int ya = std::clamp(y0, 0, l.height - 1), yb = std::clamp(y0 + 1, 0, l.height - 1);
    const float w[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
    const size_t idx[4] = {
        (size_t(ya) * l.width + xa) * channels, (size_t(ya) * l.width + xb) * channels,
        (size_t(yb) * l.width + xa) * channels, (size_t(yb) * l.width + xb) * channels};
    for (int c = 0; c < count; ++c) {
        float s = 0.0f;
        for (int k = 0; k < 4; ++k) s += w[k] * l.data[idx[k] + c];
        out[c] = s;
    }
}

// Bilinear sample of the source image (image uv, no rotation) times scale.
glm::vec3 source_sample(const EnvironmentMap& env, glm::vec2 uv) {
    const Image& img = env.image();
    const float fx = uv.x * static_cast<float>(img.width) - 0.5f;
    const float fy = uv.y * static_cast<float>(img.height) - 0.5f;
    const float x0f = std::floor(fx), y0f = std::floor(fy);
    const float tx = fx - x0f, ty = fy - y0f;
    const int x0 = static_cast<int>(x0f), y0 = static_cast<int>(y0f);
    auto texel = [&](int x, int y) {
        return img.at(((x % img.width) + img.width) % img.width, std::clamp(y, 0, img.height - 1));
    };
    const glm::vec3 c = (1 - tx) * (1 - ty) * texel(x0, y0) + tx * (1 - ty) * texel(x0 + 1, y0) +
                        (1 - tx) * ty * texel(x0, y0 + 1) + tx * ty * texel(x0 + 1, y0 + 1);
    return c * env.scale();
}

template <typename F>
void parallel_rows(int rows, F&& f) {
    // Isolated: the prefilter may run inside a render task while other
    // render tasks wait for it (kneiphof2025_environment_for holds a lock);
    // without isolation this thread could pick up one of them and deadlock.
    tbb::this_task_arena::isolate([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, rows), [&](const tbb::blocked_range<int>& r) {
            for (int y = r.begin(); y < r.end(); ++y) f(y);
        });
    });
}

void check_options(const Kneiphof2025PrefilterOptions& o) {
    if (o.levels != 4 && o.levels != 8)
        fail("kneiphof2025: levels must be 4 or 8 (003 §4), got {}", o.levels);
    if (!(o.black_level >= 1e-8f && o.black_level <= 1.0f))
        fail("kneiphof2025: black_level must be in [1e-8, 1], got {}", o.black_level);
    if (o.base_width < 16 || (o.base_width & (o.base_width - 1)) != 0 || o.base_width > 8192)
        fail("kneiphof2025: base_width must be a power of two in [16, 8192], got {}", o.base_width);
    if (o.mip_count < 2 || o.mip_count > 33)
        fail("kneiphof2025: mip_count must be in [2, 33], got {}", o.mip_count);
    if (o.samples < 1 || o.samples > 65536)
        fail("kneiphof2025: samples must be in [1, 65536], got {}", o.samples);
}

}  // namespace

glm::vec3 kneiphof2025_map_to_world(glm::vec3 d, float rotation_rad) {
    const float c = std::cos(rotation_rad), s = std::sin(rotation_rad);
    return glm::normalize(glm::vec3(d.x * c - d.z * s, d.y, d.z * c + d.x * s));
}

Kneiphof2025Environment::Kneiphof2025Environment(const EnvironmentMap& env,
                                                 const Kneiphof2025PrefilterOptions& o,
                                                 ProgressReporter* progress)
    : levels_(o.levels) {
    check_options(o);
    rotation_rad_ = glm::radians(env.rotation_deg());
    const int C = channels();
    // Internally one more channel: the sources' luminance (Kneiphof2025Sources),
    // filtered with the others and split off into source_mips_ at the end. The
    // channels are independent, so the first C are what they were without it.
    const int C1 = C + 1;
    const int W = o.base_width, H = o.base_width / 2;

    // Level 0: the radiance resampled to W x H (s x s bilinear samples per
    // texel when the source is larger, a box filter of its texels).
    Kneiphof2025Level base;
    base.width = W;
    base.height = H;
    base.data.assign(size_t(W) * H * C1, 0.0f);
    const int ss = std::max(1, (env.image().width + W - 1) / W);
    std::vector<float> lum(size_t(W) * H);
    parallel_rows(H, [&](int y) {
        for (int x = 0; x < W; ++x) {
            glm::vec3 c(0.0f);
            for (int j = 0; j < ss; ++j)
                for (int i = 0; i < ss; ++i)
                    c += source_sample(env, {(x + (i + 0.5f) / ss) / W, (y + (j + 0.5f) / ss) / H});
            c /= static_cast<float>(ss * ss);
            float* t = &base.data[(size_t(y) * W + x) * C1];
            t[0] = c.x;
            t[1] = c.y;
            t[2] = c.z;
            lum[size_t(y) * W + x] = std::max(luminance(c), 0.0f);
        }
        if (progress) progress->update();
    });

    // Eq. 18: L^(1) = 0, L^(k) = exp(lerp(log lo, log hi, (k-1)/(K-1))) for
    // k > 1, lo = max(min L, black level), hi = max L (luminance, Rec.709).
    min_luminance_ = *std::min_element(lum.begin(), lum.end());
    max_luminance_ = *std::max_element(lum.begin(), lum.end());
    radiance_levels_ =
        kneiphof2025_radiance_levels(min_luminance_, max_luminance_, levels_, o.black_level);
    for (size_t i = 0; i < lum.size(); ++i) partition(lum[i], &base.data[i * C1 + 3]);
    find_sources(W, H, base.data, C1);

    // Source pyramid for filtered importance sampling: 2 x 2 box reductions.
    std::vector<Kneiphof2025Level> pyramid{base};
    while (pyramid.back().width > 2) {
        const Kneiphof2025Level& s = pyramid.back();
        Kneiphof2025Level d;
        d.width = s.width / 2;
        d.height = std::max(1, s.height / 2);
        d.data.assign(size_t(d.width) * d.height * C1, 0.0f);
        const int sy = s.height > 1 ? 2 : 1;
        for (int y = 0; y < d.height; ++y)
            for (int x = 0; x < d.width; ++x)
                for (int c = 0; c < C1; ++c) {
                    float sum = 0.0f;
                    for (int j = 0; j < sy; ++j)
                        for (int i = 0; i < 2; ++i)
                            sum += s.data[(size_t(y * sy + j) * s.width + x * 2 + i) * C1 + c];
                    d.data[(size_t(y) * d.width + x) * C1 + c] = sum / static_cast<float>(2 * sy);
                }
        pyramid.push_back(std::move(d));
    }
    auto pyramid_fetch = [&](glm::vec2 uv, float lod, float* out, float* tmp) {
        const float l = std::clamp(lod, 0.0f, static_cast<float>(pyramid.size() - 1));
        const int l0 = static_cast<int>(std::floor(l));
        const int l1 = std::min(l0 + 1, static_cast<int>(pyramid.size()) - 1);
        const float t = l - static_cast<float>(l0);
        bilinear(pyramid[l0], C1, uv, out, C1);
        if (t > 0.0f && l1 != l0) {
            bilinear(pyramid[l1], C1, uv, tmp, C1);
            for (int c = 0; c < C1; ++c) out[c] += t * (tmp[c] - out[c]);
        }
    };

    // Eq. 11 / 21: every channel filtered by the same kernel p(wi) ~ D(h) <n, wi>
    // with n = v = r. Sample solid angle vs texel solid angle gives the LOD
    // (Colbert & Krivanek 2007). Without Karis' +1 LOD bias: with it, the
    // GGX tail samples read levels that average the sky with the ground and
    // the filtered radiance was 10-27 % off a brute-force kernel integral at
    // sqrt(alpha) = 0.5-0.7 (forest.exr); without it <= 3 % except ~10 %
    // just below the horizon.
    mips_.push_back(std::move(base));
    for (int m = 1; m < o.mip_count; ++m) {
        const float r = static_cast<float>(m) / static_cast<float>(o.mip_count - 1);
        Kneiphof2025Level lvl;
        lvl.width = W;
        lvl.height = H;
        lvl.data.assign(size_t(lvl.width) * lvl.height * C1, 0.0f);
        const std::vector<Kneiphof2025KernelSample> kernel =
            kneiphof2025_prefilter_kernel(r, o.samples, W, H);
        parallel_rows(lvl.height, [&](int y) {
            std::vector<float> acc(C1), val(C1), tmp(C1);
            for (int x = 0; x < lvl.width; ++x) {
                const glm::vec3 n =
                    map_direction({(x + 0.5f) / lvl.width, (y + 0.5f) / lvl.height});
                // Orthonormal basis (Duff et al. 2017).
                const float sign = std::copysign(1.0f, n.z);
                const float a = -1.0f / (sign + n.z);
                const float b = n.x * n.y * a;
                const glm::vec3 t(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
                const glm::vec3 bt(b, sign + n.y * n.y * a, -n.y);
                std::fill(acc.begin(), acc.end(), 0.0f);
                float wsum = 0.0f;
                for (const Kneiphof2025KernelSample& k : kernel) {
                    const glm::vec3 d = k.l.x * t + k.l.y * bt + k.l.z * n;
                    pyramid_fetch(map_uv(d, 0.0f), k.lod, val.data(), tmp.data());
                    for (int c = 0; c < C1; ++c) acc[c] += k.weight * val[c];
                    wsum += k.weight;
                }
                float* out = &lvl.data[(size_t(y) * lvl.width + x) * C1];
                for (int c = 0; c < C1; ++c) out[c] = wsum > 0.0f ? acc[c] / wsum : 0.0f;
            }
            if (progress) progress->update();
        });
        mips_.push_back(std::move(lvl));
    }
    // Split the sources channel off: mips_ keep the layout of 3 + K channels.
    for (Kneiphof2025Level& l : mips_) {
        const size_t n = size_t(l.width) * size_t(l.height);
        Kneiphof2025Level source_level;
        source_level.width = l.width;
        source_level.height = l.height;
        source_level.data.resize(n);
        std::vector<float> packed(n * size_t(C));
        for (size_t i = 0; i < n; ++i) {
            std::copy_n(&l.data[i * C1], C, &packed[i * C]);
            source_level.data[i] = l.data[i * C1 + C];
        }
        l.data = std::move(packed);
        source_mips_.push_back(std::move(source_level));
    }
}

void Kneiphof2025Environment::find_sources(int W, int H, std::vector<float>& base, int stride) {
    Image rgb(W, H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float* t = &base[(size_t(y) * W + x) * size_t(stride)];
            rgb.at(x, y) = glm::vec3(t[0], t[1], t[2]);
        }
    const EnvironmentSourceSplit split = split_environment_sources(
        rgb, Kneiphof2025Sources::kSamples, Kneiphof2025Sources::kTexelContrast);
    if (split.directions.empty()) return;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            base[(size_t(y) * W + x) * size_t(stride) + size_t(stride) - 1] =
                std::max(luminance(rgb.at(x, y)) - luminance(split.residual.at(x, y)), 0.0f);
    glm::vec3 total(0.0f);
    for (size_t k = 0; k < split.directions.size(); ++k) {
        sources_.map_directions.push_back(split.directions[k]);
        sources_.directions.push_back(
            kneiphof2025_map_to_world(split.directions[k], rotation_rad_));
        sources_.powers.push_back(split.powers[k]);
        sources_.radii.push_back(split.radii[k]);
        total += split.powers[k];
    }
    sources_.color = total / std::max(luminance(total), 1e-30f);
}

void Kneiphof2025Environment::partition(float L, float* w) const {
    // Eq. 19 (kneiphof2025_partition.glsl).
    const auto& lv = radiance_levels_;
    glm::vec4 wa, wb;
    shader::kneiphof2025_partition(L, levels_, glm::vec4(lv[0], lv[1], lv[2], lv[3]),
                                   glm::vec4(lv[4], lv[5], lv[6], lv[7]), wa, wb);
    for (int k = 0; k < levels_; ++k) w[k] = k < 4 ? wa[k] : wb[k - 4];
}

std::array<float, 8> kneiphof2025_radiance_levels(float min_luminance, float max_luminance,
                                                  int levels, float black_level) {
    // Eq. 18: L^(1) = 0, L^(k) = exp(lerp(log lo, log hi, (k-1)/(K-1))) for
    // k > 1, lo = max(min L, black level), hi = max L (luminance, Rec.709).
    const float lo = std::max(min_luminance, black_level);
    const float hi = std::max(max_luminance, lo);
    std::array<float, 8> L{};
    for (int k = 1; k < levels; ++k) {
        const float a = static_cast<float>(k) / static_cast<float>(levels - 1);
        L[static_cast<size_t>(k)] = std::exp(std::log(lo) + a * (std::log(hi) - std::log(lo)));
    }
    L[static_cast<size_t>(levels - 1)] = hi;  // exactly the max: no texel above the top level
    return L;
}

std::vector<Kneiphof2025KernelSample> kneiphof2025_prefilter_kernel(float roughness, int samples,
                                                                    int width, int height) {
    // Eq. 11 / 21: p(wi) ~ D(h) <n, wi> with n = v = r, GGX alpha = roughness^2.
    // Sample solid angle vs texel solid angle gives the LOD (Colbert &
    // Krivanek 2007), without Karis' +1 bias (see the constructor).
    const float alpha = std::max(roughness * roughness, 1e-4f);
    const float texel_solid_angle =
        4.0f * kPi / (static_cast<float>(width) * static_cast<float>(height));
    std::vector<Kneiphof2025KernelSample> kernel;
    for (int s = 0; s < samples; ++s) {
        const glm::vec3 h = sample_ggx_cos(alpha, hammersley(s, samples));
        const glm::vec3 l = 2.0f * h.z * h - glm::vec3(0, 0, 1);
        if (l.z <= 0.0f) continue;
        const float pdf = d_ggx(h, alpha) * 0.25f;  // D(h) <n,h> / (4 <v,h>), n = v
        const float omega_s = 1.0f / (static_cast<float>(samples) * pdf);
        kernel.push_back({l, l.z, std::max(0.5f * std::log2(omega_s / texel_solid_angle), 0.0f)});
    }
    return kernel;
}

void Kneiphof2025Environment::fetch_level(int level, glm::vec2 uv, float* out, int count) const {
    bilinear(mips_[level], channels(), uv, out, count);
}

void Kneiphof2025Environment::fetch(glm::vec3 dir, float roughness, float* out) const {
    fetch_channels(dir, roughness, out, channels());
}

glm::vec4 Kneiphof2025Environment::fetch_radiance_sources(glm::vec3 dir, float roughness) const {
    const glm::vec3 rgb = fetch_radiance(dir, roughness);
    if (sources_.empty()) return glm::vec4(rgb, 0.0f);
    // The same bilinear and level blend as fetch_channels, on the sources channel.
    const glm::vec2 uv = map_uv(dir, rotation_rad_);
    const int last = static_cast<int>(source_mips_.size()) - 1;
    const float l = std::clamp(roughness, 0.0f, 1.0f) * static_cast<float>(last);
    const int l0 = std::min(static_cast<int>(std::floor(l)), last);
    const int l1 = std::min(l0 + 1, last);
    const float t = l - static_cast<float>(l0);
    float a = 0.0f;
    bilinear(source_mips_[l0], 1, uv, &a, 1);
    if (t > 0.0f && l1 != l0) {
        float b = 0.0f;
        bilinear(source_mips_[l1], 1, uv, &b, 1);
        a += t * (b - a);
    }
    return glm::vec4(rgb, a);
}

glm::vec3 Kneiphof2025Environment::fetch_radiance(glm::vec3 dir, float roughness) const {
    float c[3];
    fetch_channels(dir, roughness, c, 3);
    return {c[0], c[1], c[2]};
}

void Kneiphof2025Environment::fetch_channels(glm::vec3 dir, float roughness, float* out,
                                             int count) const {
    const glm::vec2 uv = map_uv(dir, rotation_rad_);
    const int last = static_cast<int>(mips_.size()) - 1;
    const float l = std::clamp(roughness, 0.0f, 1.0f) * static_cast<float>(last);
    const int l0 = std::min(static_cast<int>(std::floor(l)), last);
    const int l1 = std::min(l0 + 1, last);
    const float t = l - static_cast<float>(l0);
    fetch_level(l0, uv, out, count);
    if (t > 0.0f && l1 != l0) {
        float tmp[11];
        fetch_level(l1, uv, tmp, count);
        for (int c = 0; c < count; ++c) out[c] += t * (tmp[c] - out[c]);
    }
}

// --- DFG / E_D table ---------------------------------------------------------

glm::vec3 Kneiphof2025DfgLut::integrate(float cos_o, float roughness, int samples) {
    const float c = std::clamp(cos_o, 1e-4f, 1.0f);
    const float alpha = std::max(roughness * roughness, 1e-4f);
    const glm::vec3 v(std::sqrt(std::max(1.0f - c * c, 0.0f)), 0.0f, c);
    double A = 0.0, B = 0.0, E = 0.0;
    for (int s = 0; s < samples; ++s) {
        // h with density D(h) cos(theta_h).
        const glm::vec3 h = sample_ggx_cos(alpha, hammersley(s, samples));
        const float vh = glm::dot(v, h);
        if (vh <= 0.0f) continue;
        const glm::vec3 l = 2.0f * vh * h - v;
        if (l.z <= 0.0f) continue;
        // E_D = int D(h) dh over the orientations that reflect v above the
        // horizon (Eq. 21: int D / (4 <h, wi>) dwi with dwi = 4 <h, wo> dh).
        E += 1.0 / h.z;
        // E_rho = int F G2 D / (4 cos_o) dwi; pdf(l) = D h.z / (4 vh).
        const float g = shader::G2_SmithCorrelated(shader::NDF_GGX, v, l, alpha, alpha);
        const float g_vis = g * vh / (h.z * c);
        const float fc = std::pow(1.0f - vh, 5.0f);
        A += (1.0f - fc) * g_vis;
        B += fc * g_vis;
    }
    const double n = samples;
    return {static_cast<float>(A / n), static_cast<float>(B / n),
            static_cast<float>(E / n / kneiphof2025_total_facet_area(alpha))};
}

namespace {
// Bumped whenever integrate() changes what it computes.
constexpr uint32_t kDfgTableVersion = 1;
constexpr const char* kDfgCacheName = "kneiphof2025_dfg";
}  // namespace

std::vector<glm::vec3> Kneiphof2025DfgLut::compute_table(ProgressReporter* progress) {
    std::vector<glm::vec3> table(size_t(kSize) * kSize);
    parallel_rows(kSize, [&](int j) {
        for (int i = 0; i < kSize; ++i)
            table[size_t(j) * kSize + i] =
                integrate((i + 0.5f) / kSize, (j + 0.5f) / kSize, kSamples);
        if (progress) progress->update();
    });
    return table;
}

uint64_t Kneiphof2025DfgLut::cache_key() {
    CacheKey key(kDfgCacheName, kDfgTableVersion);
    key.add(kSize).add(kSamples);
    return key.value();
}

std::vector<glm::vec3> Kneiphof2025DfgLut::load_or_compute_table() {
    if (const auto bytes = disk_cache_load(kDfgCacheName, cache_key())) {
        ByteReader in(*bytes);
        std::vector<glm::vec3> table;
        if (in.get_vector(table) && in.at_end() && table.size() == size_t(kSize) * kSize)
            return table;
    }
    ProgressReporter progress(kSize,
                              fmt::format("kneiphof2025 DFG table {}x{}, {} samples an entry "
                                          "(cached afterwards)",
                                          kSize, kSize, kSamples),
                              false);
    std::vector<glm::vec3> table = compute_table(&progress);
    progress.done();
    ByteWriter out;
    out.put_vector(table);
    disk_cache_store(kDfgCacheName, cache_key(), out.bytes);
    return table;
}

Kneiphof2025DfgLut::Kneiphof2025DfgLut() : table_(load_or_compute_table()) {}

const Kneiphof2025DfgLut& Kneiphof2025DfgLut::get() {
    static const Kneiphof2025DfgLut lut;
    return lut;
}

glm::vec3 Kneiphof2025DfgLut::lookup(float cos_o, float roughness) const {
    const float fx = std::clamp(cos_o * kSize - 0.5f, 0.0f, float(kSize - 1));
    const float fy = std::clamp(roughness * kSize - 0.5f, 0.0f, float(kSize - 1));
    const int x0 = std::min(static_cast<int>(fx), kSize - 2),
              y0 = std::min(static_cast<int>(fy), kSize - 2);
    const float tx = fx - x0, ty = fy - y0;
    auto at = [&](int x, int y) { return table_[size_t(y) * kSize + x]; };
    return (1 - tx) * (1 - ty) * at(x0, y0) + tx * (1 - ty) * at(x0 + 1, y0) +
           (1 - tx) * ty * at(x0, y0 + 1) + tx * ty * at(x0 + 1, y0 + 1);
}

std::vector<float> Kneiphof2025DfgLut::rgba_texture() const {
    constexpr int n = kSize;
    std::vector<float> rgba(static_cast<size_t>(n) * n * 4, 0.0f);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec3 v =
                lookup((static_cast<float>(i) + 0.5f) / n, (static_cast<float>(j) + 0.5f) / n);
            float* t = &rgba[(static_cast<size_t>(j) * n + i) * 4];
            t[0] = v.x;
            t[1] = v.y;
            t[2] = v.z;
        }
    return rgba;
}

// --- on-disk cache of the prefiltered maps ------------------------------------

namespace {
// Bumped whenever the constructor (or find_sources, partition, the kernel, the
// radiance levels) changes what it computes, or write() / read() their layout.
constexpr uint32_t kPrefilterTableVersion = 2;
// The payload's own layout version, its first field (read() rejects others).
constexpr uint32_t kPrefilterLayoutVersion = 2;
static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
}  // namespace

uint64_t Kneiphof2025Environment::cache_key(const EnvironmentMap& env,
                                            const Kneiphof2025PrefilterOptions& o) {
    CacheKey key(kCacheName, kPrefilterTableVersion);
    const Image& img = env.image();
    key.add(img.width).add(img.height);
    key.add_bytes(img.pixels.data(), img.pixels.size() * sizeof(glm::vec3));
    key.add(env.scale());
    key.add(o.levels).add(o.black_level).add(o.base_width).add(o.mip_count).add(o.samples);
    key.add(EnvironmentSourceCriteria::kContrast)
        .add(EnvironmentSourceCriteria::kFraction)
        .add(Kneiphof2025Sources::kSamples)
        .add(Kneiphof2025Sources::kTexelContrast);
    return key.value();
}

// Layout (native endianness, as every table cache): u32 layout version;
// i32 K, width, height, level count; f32 radiance levels[8], min and max
// luminance; the sources (u64 count + f32 map_directions[3] each, the same
// for powers[3] and radii, then f32 color[3]; their world directions are not
// stored: the rotation is not in the key); then each level's data and each
// sources level's data as u64 count + f32 values.
void Kneiphof2025Environment::write(ByteWriter& out) const {
    out.put(kPrefilterLayoutVersion);
    out.put(int32_t(levels_));
    out.put(int32_t(mips_.front().width));
    out.put(int32_t(mips_.front().height));
    out.put(int32_t(mips_.size()));
    out.put(radiance_levels_);
    out.put(min_luminance_);
    out.put(max_luminance_);
    out.put_vector(sources_.map_directions);
    out.put_vector(sources_.powers);
    out.put_vector(sources_.radii);
    out.put(sources_.color);
    for (const Kneiphof2025Level& l : mips_) out.put_vector(l.data);
    for (const Kneiphof2025Level& l : source_mips_) out.put_vector(l.data);
}

bool Kneiphof2025Environment::read(ByteReader& in, const Kneiphof2025PrefilterOptions& o,
                                   float rotation_deg) {
    uint32_t version = 0;
    int32_t k = 0, w = 0, h = 0, count = 0;
    if (!(in.get(version) && version == kPrefilterLayoutVersion && in.get(k) && in.get(w) &&
          in.get(h) && in.get(count)))
        return false;
    if (k != o.levels || w != o.base_width || h != o.base_width / 2 || count != o.mip_count)
        return false;
    levels_ = k;
    rotation_rad_ = glm::radians(rotation_deg);
    if (!(in.get(radiance_levels_) && in.get(min_luminance_) && in.get(max_luminance_) &&
          in.get_vector(sources_.map_directions) && in.get_vector(sources_.powers) &&
          in.get_vector(sources_.radii) && in.get(sources_.color)))
        return false;
    const size_t n = sources_.map_directions.size();
    if (n > size_t(Kneiphof2025Sources::kSamples) || sources_.powers.size() != n ||
        sources_.radii.size() != n)
        return false;
    sources_.directions.clear();
    for (const glm::vec3& d : sources_.map_directions)
        sources_.directions.push_back(kneiphof2025_map_to_world(d, rotation_rad_));
    const size_t texels = size_t(w) * size_t(h);
    auto read_levels = [&](std::vector<Kneiphof2025Level>& levels, size_t channels) {
        levels.resize(size_t(count));
        for (Kneiphof2025Level& l : levels) {
            l.width = w;
            l.height = h;
            if (!in.get_vector(l.data) || l.data.size() != texels * channels) return false;
        }
        return true;
    };
    return read_levels(mips_, size_t(channels())) && read_levels(source_mips_, 1) && in.at_end();
}

std::shared_ptr<const Kneiphof2025Environment> Kneiphof2025Environment::load_or_build(
    const EnvironmentMap& env, const Kneiphof2025PrefilterOptions& o, bool* from_cache) {
    check_options(o);
    const uint64_t key = cache_key(env, o);
    if (from_cache) *from_cache = false;
    if (const auto bytes = disk_cache_load(kCacheName, key)) {
        ByteReader in(*bytes);
        std::shared_ptr<Kneiphof2025Environment> e(new Kneiphof2025Environment());
        if (e->read(in, o, env.rotation_deg())) {
            if (from_cache) *from_cache = true;
            return e;
        }
        disk_cache_reject(kCacheName, key, "its maps do not have the sizes the options imply");
    }
    const int rows = o.base_width / 2;
    ProgressReporter progress(int64_t(o.mip_count) * rows,
                              fmt::format("kneiphof2025 prefiltered maps, K = {}, {} levels of "
                                          "{}x{}, {} samples a texel (cached afterwards)",
                                          o.levels, o.mip_count, o.base_width, rows, o.samples),
                              false);
    auto e = std::make_shared<const Kneiphof2025Environment>(env, o, &progress);
    progress.done();
    ByteWriter out;
    e->write(out);
    disk_cache_store(kCacheName, key, out.bytes);
    return e;
}

// --- in-memory cache ---------------------------------------------------------

std::shared_ptr<const Kneiphof2025Environment> kneiphof2025_environment_for(
    const std::shared_ptr<const EnvironmentMap>& env, int levels, float black_level) {
    struct Entry {
        std::weak_ptr<const EnvironmentMap> owner;
        std::shared_ptr<const Kneiphof2025Environment> value;
    };
    static std::mutex mutex;
    static std::map<std::tuple<const EnvironmentMap*, int, float>, Entry> cache;
    if (!env) fail("kneiphof2025: environment light without a map");
    std::lock_guard<std::mutex> lock(mutex);
    const auto key = std::make_tuple(env.get(), levels, black_level);
    Entry& e = cache[key];
    if (!e.value || e.owner.lock() != env) {
        // The maps of a freed environment can never be used again (a new map
        // at its address is told apart by `owner`): drop them, or every scene
        // load of a long process (compare's realizations, a Python sweep)
        // would keep its prefiltered maps for good. Only on a miss: this is
        // called per shading call, and a map is only freed ahead of a new one.
        for (auto it = cache.begin(); it != cache.end();) {
            if (it->first != key && it->second.owner.expired())
                it = cache.erase(it);
            else
                ++it;
        }
        Kneiphof2025PrefilterOptions o;
        o.levels = levels;
        o.black_level = black_level;
        e.value = Kneiphof2025Environment::load_or_build(*env, o);
        e.owner = env;
    }
    return e.value;
}

}  // namespace glintlab
