#include "glintlab/realtime/gpu_bloom.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <epoxy/gl.h>
#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/core/shader_assembly.h"
#include "glintlab/gl/gl_handles.h"
#include "glintlab/gl/gl_program.h"

namespace glintlab::gl {
namespace {

// One bloom pass, realtime/shaders/bloom_<pass>.comp.glsl.
GLuint compute_program(const char* pass, const char* what) {
    return link_compute_program(
        assemble_shader(fmt::format("glintlab/realtime/shaders/bloom_{}.comp.glsl", pass)), what);
}

// core/bloom_blur.cpp gaussian_taps and source_scales, in the same precision.
std::vector<float> gaussian_taps(float sigma) {
    const int radius = std::max(1, static_cast<int>(std::ceil(4.0f * sigma)));
    std::vector<float> taps(static_cast<size_t>(2 * radius + 1));
    double sum = 0.0;
    for (int k = -radius; k <= radius; ++k) {
        const double w = std::exp(-0.5 * double(k) * double(k) / (double(sigma) * sigma));
        taps[static_cast<size_t>(k + radius)] = static_cast<float>(w);
        sum += w;
    }
    for (float& w : taps) w = static_cast<float>(double(w) / sum);
    return taps;
}

std::vector<float> source_scales(const std::vector<float>& taps, int n) {
    const int radius = static_cast<int>(taps.size() / 2);
    std::vector<float> scale(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        double inside = 0.0;
        for (int k = -radius; k <= radius; ++k)
            if (i + k >= 0 && i + k < n) inside += taps[static_cast<size_t>(k + radius)];
        scale[static_cast<size_t>(i)] = static_cast<float>(1.0 / inside);
    }
    return scale;
}

Texture rgba32f(int w, int h) {
    Texture t = make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(t.get(), 1, GL_RGBA32F, w, h);
    return t;
}

}  // namespace

struct GpuBloom::Impl {
    Program extract, blur, composite;
    Texture bright, temp, glow, result;
    Buffer taps, scales;
    int width = 0, height = 0;
};

GpuBloom::GpuBloom() : impl_(std::make_unique<Impl>()) {
    impl_->extract = Program(compute_program("extract", "bloom extract"));
    impl_->blur = Program(compute_program("blur", "bloom blur"));
    impl_->composite = Program(compute_program("composite", "bloom composite"));
}

GpuBloom::~GpuBloom() = default;

unsigned GpuBloom::apply(unsigned hdr, int w, int h, const BloomSettings& settings) {
    validate(settings);
    if (settings.strength == 0.0f) return hdr;
    Impl& r = *impl_;
    if (w != r.width || h != r.height) {
        r.bright = rgba32f(w, h);
        r.temp = rgba32f(w, h);
        r.glow = rgba32f(w, h);
        r.result = rgba32f(w, h);
        r.width = w;
        r.height = h;
    }
    const GLuint gx = static_cast<GLuint>((w + 15) / 16), gy = static_cast<GLuint>((h + 15) / 16);
    auto barrier = [] { glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT); };

    glUseProgram(r.extract.get());
    glProgramUniform1f(r.extract.get(), glGetUniformLocation(r.extract.get(), "u_threshold"),
                       settings.threshold);
    glBindImageTexture(0, hdr, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, r.bright.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(gx, gy, 1);
    barrier();

    // bloom_blur: the mean of Gaussians of sigma = radius x {1/4, 1/2, 1, 2}.
    const GLuint b = r.blur.get();
    glUseProgram(b);
    const float octaves[] = {0.25f, 0.5f, 1.0f, 2.0f};
    for (int o = 0; o < 4; ++o) {
        const std::vector<float> taps = gaussian_taps(octaves[o] * settings.radius_px);
        const int radius = static_cast<int>(taps.size() / 2);
        glProgramUniform1i(b, glGetUniformLocation(b, "u_radius"), radius);
        r.taps = make_buffer();
        glNamedBufferStorage(r.taps.get(), static_cast<GLsizeiptr>(taps.size() * sizeof(float)),
                             taps.data(), 0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, r.taps.get());
        for (int axis = 0; axis < 2; ++axis) {
            const std::vector<float> scales = source_scales(taps, axis == 0 ? w : h);
            r.scales = make_buffer();
            glNamedBufferStorage(r.scales.get(),
                                 static_cast<GLsizeiptr>(scales.size() * sizeof(float)),
                                 scales.data(), 0);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, r.scales.get());
            glProgramUniform1i(b, glGetUniformLocation(b, "u_axis"), axis);
            // Rows: bright -> temp; columns: temp -> glow, accumulated with weight 1/4.
            glProgramUniform1i(b, glGetUniformLocation(b, "u_accumulate"),
                               axis == 1 && o > 0 ? 1 : 0);
            glProgramUniform1f(b, glGetUniformLocation(b, "u_weight"), axis == 0 ? 1.0f : 0.25f);
            glBindImageTexture(0, axis == 0 ? r.bright.get() : r.temp.get(), 0, GL_FALSE, 0,
                               GL_READ_ONLY, GL_RGBA32F);
            glBindImageTexture(1, axis == 0 ? r.temp.get() : r.glow.get(), 0, GL_FALSE, 0,
                               GL_READ_WRITE, GL_RGBA32F);
            glDispatchCompute(gx, gy, 1);
            barrier();
        }
    }

    const GLuint c = r.composite.get();
    glUseProgram(c);
    glProgramUniform1f(c, glGetUniformLocation(c, "u_strength"), settings.strength);
    glBindImageTexture(0, hdr, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, r.bright.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(2, r.glow.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(3, r.result.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(gx, gy, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
    return r.result.get();
}

}  // namespace glintlab::gl
