#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter_gpu.h"

#include <algorithm>
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

Kneiphof2025GpuPrefilter::Kneiphof2025GpuPrefilter(const Kneiphof2025PrefilterOptions& o)
    : options_(o), width_(o.base_width), height_(o.base_width / 2), pyramid_levels_(0) {
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
    for (int m = 1; m < o.mip_count; ++m) {
        const float r = static_cast<float>(m) / static_cast<float>(o.mip_count - 1);
        kernel_first_[static_cast<size_t>(m)] = static_cast<int>(kernels.size() / 8);
        for (const Kneiphof2025KernelSample& k :
             kneiphof2025_prefilter_kernel(r, o.samples, width_, height_)) {
            kernels.insert(kernels.end(), {k.l.x, k.l.y, k.l.z, k.weight, k.lod, 0.0f, 0.0f, 0.0f});
            ++kernel_count_[static_cast<size_t>(m)];
        }
    }
    kernels_ = make_buffer();
    if (kernels.empty()) kernels.assign(8, 0.0f);
    glNamedBufferStorage(kernels_.get(), static_cast<GLsizeiptr>(kernels.size() * sizeof(float)),
                         kernels.data(), 0);
    radiance_ = make_latlong_array(width_, height_, o.mip_count);
    weights_a_ = make_latlong_array(width_, height_, o.mip_count);
    weights_b_ = make_latlong_array(width_, height_, o.mip_count);
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

    // Pass 5: the prefiltered layers.
    const GLuint pf = filter_.get();
    for (int c = 0; c < 3; ++c) glBindTextureUnit(static_cast<GLuint>(c), pyramid_[c].get());
    glBindImageTexture(0, radiance_.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, weights_a_.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(2, weights_b_.get(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, kernels_.get());
    glUseProgram(pf);
    for (int m = 0; m < options_.mip_count; ++m) {
        glProgramUniform1i(pf, glGetUniformLocation(pf, "u_layer"), m);
        glProgramUniform1i(pf, glGetUniformLocation(pf, "u_first"),
                           kernel_first_[static_cast<size_t>(m)]);
        glProgramUniform1i(pf, glGetUniformLocation(pf, "u_count"),
                           kernel_count_[static_cast<size_t>(m)]);
        glDispatchCompute(groups(W), groups(H), 1);
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
