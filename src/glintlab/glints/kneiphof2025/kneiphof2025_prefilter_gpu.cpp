#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include <epoxy/gl.h>
#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/core/shader_assembly.h"
#include "glintlab/gl/gl_program.h"

namespace glintlab::gl {
namespace {

constexpr int kGroup = 8;  // 8 x 8 invocations per work group

// Resolution::Reduced: the largest shift s_m (a grid 4 x 4 times coarser than
// the base, 64 x 32 at the default 256 x 128). Measured on the 8 Blender
// studio lights (docs/BENCHMARKS.md): with s_m = 3, 4 (32 x 16, 16 x 8) for
// sqrt(alpha) >= 1/2 the mean difference to the CPU layers reaches 2.7 % of a
// channel's range (layer 6); capped at 2 it stays <= 0.6 %, for a cost
// (layers 4-6 at 1/16 of a full layer each) within the timing noise.
constexpr int kMaxReducedShift = 2;

GLuint compile(const char* pass, const char* what) {
    return link_compute_program(
        assemble_shader(
            fmt::format("glintlab/glints/kneiphof2025/kneiphof2025_prefilter_{}.comp.glsl", pass)),
        what);
}

GLuint groups(int n) {
    return static_cast<GLuint>((n + kGroup - 1) / kGroup);
}

}  // namespace

Texture make_latlong_array(int width, int height, int layers) {
    Texture t = make_texture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(t.get(), 1, GL_RGBA32F, width, height, layers);
    glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

Kneiphof2025GpuPrefilter::Kneiphof2025GpuPrefilter(const Kneiphof2025PrefilterOptions& o,
                                                   Resolution resolution)
    : options_(o),
      resolution_(resolution),
      width_(o.base_width),
      height_(o.base_width / 2),
      pyramid_levels_(0),
      coarse_levels_(1) {
    // The CPU's ranges (kneiphof2025_prefilter.cpp), and the kernel array size.
    if (o.levels != 4 && o.levels != 8)
        fail("kneiphof2025 (GPU prefilter): levels must be 4 or 8 (003 §4), got {}", o.levels);
    if (!(o.black_level >= 1e-8f && o.black_level <= 1.0f))
        fail("kneiphof2025 (GPU prefilter): black_level must be in [1e-8, 1], got {}",
             o.black_level);
    if (o.base_width < 16 || (o.base_width & (o.base_width - 1)) != 0 || o.base_width > 8192)
        fail(
            "kneiphof2025 (GPU prefilter): base_width must be a power of two in [16, 8192], got {}",
            o.base_width);
    if (o.mip_count < 2 || o.mip_count > 33)
        fail("kneiphof2025 (GPU prefilter): mip_count must be in [2, 33], got {}", o.mip_count);
    if (o.samples < 1 || o.samples > 65536)
        fail("kneiphof2025 (GPU prefilter): samples must be in [1, 65536], got {}", o.samples);
    base_ = Program(compile("base", "kneiphof2025 prefilter: base level"));
    partition_ = Program(compile("partition", "kneiphof2025 prefilter: partition"));
    reduce_ = Program(compile("reduce", "kneiphof2025 prefilter: pyramid"));
    filter_ = Program(compile("filter", "kneiphof2025 prefilter: GGX filter"));
    if (resolution_ == Resolution::Reduced)
        upsample_ = Program(compile("upsample", "kneiphof2025 prefilter: upsampling"));
    range_ = make_buffer();
    glNamedBufferStorage(range_.get(), 2 * sizeof(GLuint), nullptr,
                         GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    // The CPU pyramid: halvings down to a width of 2 (height >= 1).
    for (int w = width_; w >= 2; w /= 2) ++pyramid_levels_;
    for (Texture& t : pyramid_) {
        t = make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(t.get(), pyramid_levels_, GL_RGBA32F, width_, height_);
        glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTextureParameteri(t.get(), GL_TEXTURE_MAX_LEVEL, pyramid_levels_ - 1);
    }
    // The kernels of layers 1 .. M-1 (the CPU's samples and LODs), one buffer.
    std::vector<float> kernels;
    kernel_first_.assign(static_cast<size_t>(o.mip_count), 0);
    kernel_count_.assign(static_cast<size_t>(o.mip_count), 0);
    shift_.assign(static_cast<size_t>(o.mip_count), 0);
    // Reduced: s_m = floor(smallest LOD of the kernel), at most
    // kMaxReducedShift and at most the shift that leaves 4 rows.
    int max_shift = 0;
    while (max_shift < kMaxReducedShift && (height_ >> (max_shift + 1)) >= 4) ++max_shift;
    for (int m = 1; m < o.mip_count; ++m) {
        const float r = static_cast<float>(m) / static_cast<float>(o.mip_count - 1);
        kernel_first_[static_cast<size_t>(m)] = static_cast<int>(kernels.size() / 8);
        float min_lod = 1e30f;
        for (const Kneiphof2025KernelSample& k :
             kneiphof2025_prefilter_kernel(r, o.samples, width_, height_)) {
            kernels.insert(kernels.end(), {k.l.x, k.l.y, k.l.z, k.weight, k.lod, 0.0f, 0.0f, 0.0f});
            ++kernel_count_[static_cast<size_t>(m)];
            min_lod = std::min(min_lod, k.lod);
        }
        if (resolution_ == Resolution::Reduced && kernel_count_[static_cast<size_t>(m)] > 0) {
            const int s = std::clamp(static_cast<int>(std::floor(min_lod)), 0, max_shift);
            shift_[static_cast<size_t>(m)] = s;
            coarse_levels_ = std::max(coarse_levels_, s + 1);
        }
    }
    kernels_ = make_buffer();
    if (kernels.empty()) kernels.assign(8, 0.0f);
    glNamedBufferStorage(kernels_.get(), static_cast<GLsizeiptr>(kernels.size() * sizeof(float)),
                         kernels.data(), 0);
    radiance_ = make_latlong_array(width_, height_, o.mip_count);
    weights_a_ = make_latlong_array(width_, height_, o.mip_count);
    weights_b_ = make_latlong_array(width_, height_, o.mip_count);
    if (coarse_levels_ > 1)
        for (Texture& t : coarse_) {
            // make_latlong_array's sampling (bilinear, u wraps, v clamps) at
            // an explicit level: level s of layer m holds the coarse layer.
            t = make_texture(GL_TEXTURE_2D_ARRAY);
            glTextureStorage3D(t.get(), coarse_levels_, GL_RGBA32F, width_, height_, o.mip_count);
            glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
            glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
            glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            glTextureParameteri(t.get(), GL_TEXTURE_MAX_LEVEL, coarse_levels_ - 1);
        }
}

Kneiphof2025GpuPrefilter::~Kneiphof2025GpuPrefilter() = default;

void Kneiphof2025GpuPrefilter::run(unsigned source, int source_width, int source_height,
                                   float scale) {
    if (source == 0 || source_width < 1 || source_height < 1)
        fail("kneiphof2025 (GPU prefilter): no source environment texture");
    const int W = width_, H = height_;
    // Pass 1: base level and luminance range.
    const GLuint init[2] = {0x7f800000u, 0u};  // +inf, 0
    glNamedBufferSubData(range_.get(), 0, sizeof(init), init);
    const GLuint pb = base_.get();
    glProgramUniform1i(pb, glGetUniformLocation(pb, "u_ss"),
                       std::max(1, (source_width + W - 1) / W));
    glProgramUniform1f(pb, glGetUniformLocation(pb, "u_scale"), scale);
    glBindTextureUnit(0, source);
    glBindImageTexture(0, pyramid_[0].get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, range_.get());
    glUseProgram(pb);
    glDispatchCompute(groups(W), groups(H), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // Pass 2: Eq. 18 on the host from the range (the CPU's function).
    GLuint bits[2] = {0, 0};
    glGetNamedBufferSubData(range_.get(), 0, sizeof(bits), bits);
    float range[2];
    std::memcpy(range, bits, sizeof(range));
    radiance_levels_ =
        kneiphof2025_radiance_levels(range[0], range[1], options_.levels, options_.black_level);
    const auto& L = radiance_levels_;

    // Pass 3: partition of the base level.
    const GLuint pp = partition_.get();
    glProgramUniform1i(pp, glGetUniformLocation(pp, "u_levels"), options_.levels);
    glProgramUniform4f(pp, glGetUniformLocation(pp, "u_levels_a"), L[0], L[1], L[2], L[3]);
    glProgramUniform4f(pp, glGetUniformLocation(pp, "u_levels_b"), L[4], L[5], L[6], L[7]);
    glBindImageTexture(0, pyramid_[0].get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, pyramid_[1].get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(2, pyramid_[2].get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glUseProgram(pp);
    glDispatchCompute(groups(W), groups(H), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // Pass 4: the box pyramid.
    glUseProgram(reduce_.get());
    for (int l = 1; l < pyramid_levels_; ++l) {
        for (int c = 0; c < 3; ++c) {
            glBindImageTexture(c, pyramid_[c].get(), l - 1, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
            glBindImageTexture(3 + c, pyramid_[c].get(), l, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        }
        glDispatchCompute(groups(std::max(1, W >> l)), groups(std::max(1, H >> l)), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);

    // Pass 5: the prefiltered layers, layer m on its (W >> s_m) x (H >> s_m)
    // grid (the output array itself at s_m = 0, else level s_m of coarse_).
    // With K = 4 the third channel group (weights 5-8) is zero everywhere:
    // its lookups are skipped (u_weights_b), the output stays zero.
    const GLuint pf = filter_.get();
    const GLuint outputs[3] = {radiance_.get(), weights_a_.get(), weights_b_.get()};
    for (int c = 0; c < 3; ++c) glBindTextureUnit(static_cast<GLuint>(c), pyramid_[c].get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, kernels_.get());
    glProgramUniform1i(pf, glGetUniformLocation(pf, "u_weights_b"), options_.levels > 4 ? 1 : 0);
    glUseProgram(pf);
    int bound_shift = -1;
    for (int m = 0; m < options_.mip_count; ++m) {
        const int s = shift_[static_cast<size_t>(m)];
        if (s != bound_shift) {
            for (int c = 0; c < 3; ++c)
                glBindImageTexture(static_cast<GLuint>(c), s == 0 ? outputs[c] : coarse_[c].get(),
                                   s, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
            bound_shift = s;
        }
        glProgramUniform1i(pf, glGetUniformLocation(pf, "u_layer"), m);
        glProgramUniform1i(pf, glGetUniformLocation(pf, "u_first"),
                           kernel_first_[static_cast<size_t>(m)]);
        glProgramUniform1i(pf, glGetUniformLocation(pf, "u_count"),
                           kernel_count_[static_cast<size_t>(m)]);
        glDispatchCompute(groups(std::max(1, W >> s)), groups(std::max(1, H >> s)), 1);
    }
    // Pass 6 (Reduced): bilinear upsampling of the coarse layers to W x H.
    if (coarse_levels_ > 1) {
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        const GLuint pu = upsample_.get();
        for (int c = 0; c < 3; ++c) {
            glBindTextureUnit(static_cast<GLuint>(c), coarse_[c].get());
            glBindImageTexture(static_cast<GLuint>(c), outputs[c], 0, GL_TRUE, 0, GL_WRITE_ONLY,
                               GL_RGBA32F);
        }
        glProgramUniform1i(pu, glGetUniformLocation(pu, "u_weights_b"),
                           options_.levels > 4 ? 1 : 0);
        glUseProgram(pu);
        for (int m = 1; m < options_.mip_count; ++m) {
            const int s = shift_[static_cast<size_t>(m)];
            if (s == 0) continue;
            glProgramUniform1i(pu, glGetUniformLocation(pu, "u_layer"), m);
            glProgramUniform1f(pu, glGetUniformLocation(pu, "u_lod"), static_cast<float>(s));
            glDispatchCompute(groups(W), groups(H), 1);
        }
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
    glUseProgram(0);
}

Kneiphof2025Level Kneiphof2025GpuPrefilter::read_layer(int layer) const {
    if (layer < 0 || layer >= options_.mip_count)
        fail("kneiphof2025 (GPU prefilter): layer {} out of [0, {})", layer, options_.mip_count);
    const int W = width_, H = height_, K = options_.levels, C = 3 + K;
    const size_t n = static_cast<size_t>(W) * static_cast<size_t>(H);
    std::vector<float> rgba[3];
    const GLuint textures[3] = {radiance_.get(), weights_a_.get(), weights_b_.get()};
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int c = 0; c < 3; ++c) {
        rgba[c].resize(n * 4);
        glGetTextureSubImage(textures[c], 0, 0, 0, layer, W, H, 1, GL_RGBA, GL_FLOAT,
                             static_cast<GLsizei>(n * 4 * sizeof(float)), rgba[c].data());
    }
    Kneiphof2025Level out;
    out.width = W;
    out.height = H;
    out.data.assign(n * static_cast<size_t>(C), 0.0f);
    for (size_t i = 0; i < n; ++i) {
        float* t = &out.data[i * static_cast<size_t>(C)];
        for (int c = 0; c < 3; ++c) t[c] = rgba[0][i * 4 + static_cast<size_t>(c)];
        for (int k = 0; k < K; ++k)
            t[3 + k] = rgba[k < 4 ? 1 : 2][i * 4 + static_cast<size_t>(k % 4)];
    }
    return out;
}

}  // namespace glintlab::gl
