#include "glintlab/glints/wang2020/wang2020_gpu_blur.h"

#include <cmath>
#include <vector>

#include <epoxy/gl.h>

#include "glintlab/core/error.h"
#include "glintlab/core/shader_assembly.h"
#include "glintlab/gl/gl_handles.h"
#include "glintlab/gl/gl_program.h"

namespace glintlab::gl {
namespace {

constexpr int kMaxSize = 31;

// wang2020_postprocess.cpp gaussian_blur's taps: σ = size / 6, normalised
// in double.
std::vector<float> taps_of(int size) {
    if (size < 1 || size % 2 == 0 || size > kMaxSize)
        fail("wang2020 GPU blur: size {} must be odd and in [1, {}]", size, kMaxSize);
    const int r = size / 2;
    const double sigma = size / 6.0;
    std::vector<double> k(static_cast<size_t>(size));
    double sum = 0.0;
    for (int i = -r; i <= r; ++i) sum += k[i + r] = std::exp(-0.5 * i * i / (sigma * sigma));
    std::vector<float> out(static_cast<size_t>(size));
    for (int i = 0; i < size; ++i) out[i] = static_cast<float>(k[i] / sum);
    return out;
}

}  // namespace

struct GpuWang2020Blur::Impl {
    Program program, add;
    Texture a, delta, b, out;
    int width = 0, height = 0;

    void resize(int w, int h) {
        if (w == width && h == height) return;
        for (Texture* t : {&a, &delta, &b, &out}) {
            *t = make_texture(GL_TEXTURE_2D);
            glTextureStorage2D(t->get(), 1, GL_RGBA32F, w, h);
        }
        width = w;
        height = h;
    }

    void pass(GLuint src, GLuint aux, GLuint dst, const std::vector<float>& taps, int axis,
              int mode, bool store_aux) {
        const GLuint p = program.get();
        glProgramUniform1fv(p, glGetUniformLocation(p, "u_taps"), static_cast<GLsizei>(taps.size()),
                            taps.data());
        glProgramUniform1i(p, glGetUniformLocation(p, "u_radius"),
                           static_cast<int>(taps.size() / 2));
        glProgramUniform1i(p, glGetUniformLocation(p, "u_axis"), axis);
        glProgramUniform1i(p, glGetUniformLocation(p, "u_mode"), mode);
        glProgramUniform1i(p, glGetUniformLocation(p, "u_store_aux"), store_aux ? 1 : 0);
        glBindImageTexture(0, src, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
        glBindImageTexture(1, aux, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
        glBindImageTexture(2, dst, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glUseProgram(p);
        glDispatchCompute(static_cast<GLuint>((width + 15) / 16),
                          static_cast<GLuint>((height + 15) / 16), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                        GL_TEXTURE_UPDATE_BARRIER_BIT);
    }
};

GpuWang2020Blur::GpuWang2020Blur() : impl_(std::make_unique<Impl>()) {
    impl_->program = Program(
        link_compute_program(assemble_shader("glintlab/glints/wang2020/wang2020_blur.comp.glsl"),
                             "wang2020 post-process blur"));
    impl_->add = Program(
        link_compute_program(assemble_shader("glintlab/glints/wang2020/wang2020_add.comp.glsl"),
                             "wang2020 post-process add"));
}

GpuWang2020Blur::~GpuWang2020Blur() = default;

unsigned GpuWang2020Blur::apply(unsigned glints, int width, int height, int occlusion_size,
                                int glint_size) {
    if (width < 1 || height < 1) fail("wang2020 GPU blur: image {}x{} is empty", width, height);
    const std::vector<float> g9 = taps_of(occlusion_size), g3 = taps_of(glint_size);
    Impl& m = *impl_;
    m.resize(width, height);
    m.pass(glints, glints, m.a.get(), g9, 0, 0, false);             // visibility along x
    m.pass(m.a.get(), m.a.get(), m.delta.get(), g9, 1, 1, false);   // δ = G9 * visibility
    m.pass(glints, m.delta.get(), m.b.get(), g3, 0, 2, false);      // rgb·δ along x
    m.pass(m.b.get(), m.delta.get(), m.out.get(), g3, 1, 1, true);  // out = G3 * (rgb·δ), a = δ
    glUseProgram(0);
    return m.out.get();
}

void GpuWang2020Blur::apply_add(unsigned glints, unsigned target, int width, int height,
                                int occlusion_size, int glint_size) {
    const GLuint blurred = apply(glints, width, height, occlusion_size, glint_size);
    glBindImageTexture(0, blurred, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, target, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    glUseProgram(impl_->add.get());
    glDispatchCompute(static_cast<GLuint>((width + 15) / 16),
                      static_cast<GLuint>((height + 15) / 16), 1);
    // Later readers of the target: read-back, sampling (tone map, bloom),
    // rendering into it.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glUseProgram(0);
}

wang2020::GlintBuffer GpuWang2020Blur::apply(const wang2020::GlintBuffer& in, int occlusion_size,
                                             int glint_size) {
    if (in.width < 1 || in.height < 1 ||
        in.texels.size() != static_cast<size_t>(in.width) * in.height)
        fail("wang2020 GPU blur: buffer {}x{} does not match {} texels", in.width, in.height,
             in.texels.size());
    Texture src = make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(src.get(), 1, GL_RGBA32F, in.width, in.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(src.get(), 0, 0, 0, in.width, in.height, GL_RGBA, GL_FLOAT,
                        in.texels.data());
    const unsigned result = apply(src.get(), in.width, in.height, occlusion_size, glint_size);
    wang2020::GlintBuffer out{in.width, in.height, std::vector<glm::vec4>(in.texels.size())};
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(result, 0, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(out.texels.size() * sizeof(glm::vec4)),
                      out.texels.data());
    return out;
}

}  // namespace glintlab::gl
