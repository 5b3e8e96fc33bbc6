#include "glintlab/glints/deliot2023/deliot2023_gpu.h"

#include <variant>

#include <epoxy/gl.h>

#include "glintlab/gl/uniform_cache.h"
#include "glintlab/glints/deliot2023/deliot2023.h"
#include "glintlab/glints/glint_desc.h"

namespace glintlab {
namespace {

static_assert(kDeliot2023NoiseUnit == 5);  // deliot2023_noise_texture_gpu.glsl

constexpr unsigned kNoiseTexture = 1u << 0;    // options[0]
constexpr unsigned kStochasticGrid = 1u << 1;  // options[1]

constexpr GpuModelOption kOptions[] = {
    {"noise_texture",
     "uniforms of the gated-Gaussian evaluations from a 64 x 64 noise texture (000 6.3) instead "
     "of the hash",
     true},
    {"stochastic_grid",
     "one of the 4 grids per pixel and frame, chosen by its weight (same mean; for temporal "
     "accumulation; a quarter of the binomials)",
     true},
};

std::string glue_path(unsigned options) {
    const bool noise = (options & kNoiseTexture) != 0;
    if ((options & kStochasticGrid) != 0)
        return noise ? "glintlab/glints/deliot2023/deliot2023_noise_texture_stochastic_gpu.glsl"
                     : "glintlab/glints/deliot2023/deliot2023_stochastic_gpu.glsl";
    return noise ? "glintlab/glints/deliot2023/deliot2023_noise_texture_gpu.glsl"
                 : "glintlab/glints/deliot2023/deliot2023_gpu.glsl";
}

class State final : public GpuModelState {
  public:
    ~State() override {
        if (noise_ != 0) glDeleteTextures(1, &noise_);
    }

    // The frame number of the stochastic grid choice (a new draw per frame).
    void begin_frame(const GpuFrame&, unsigned) override { ++frame_; }
    void prepare(unsigned program, gl::UniformCache& u, const GlintDesc& desc, const GpuFrame&,
                 unsigned options) override {
        auto loc = [&](const char* name) { return u.location(program, name); };
        const auto& p = std::get<Deliot2023Params>(desc.params);
        glProgramUniform1f(program, loc("u_deliot2023_microfacet_roughness"),
                           p.microfacet_roughness);
        glProgramUniform1f(program, loc("u_deliot2023_screen_space_scale"), p.screen_space_scale);
        glProgramUniform1f(program, loc("u_deliot2023_density_randomization"),
                           p.density_randomization);
        glProgramUniform1i(program, loc("u_deliot2023_original_defects"),
                           p.original_defects ? 1 : 0);
        glProgramUniform1i(program, loc("u_deliot2023_conditional"),
                           p.conditional_gaussian ? 1 : 0);
        if ((options & kStochasticGrid) != 0)
            glProgramUniform1ui(program, loc("u_deliot2023_frame"), frame_);
        if ((options & kNoiseTexture) == 0) return;
        if (noise_ == 0) {
            const std::vector<float> pairs = deliot2023_noise_pairs();
            glCreateTextures(GL_TEXTURE_2D, 1, &noise_);
            glTextureStorage2D(noise_, 1, GL_RG32F, 64, 64);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
            glTextureSubImage2D(noise_, 0, 0, 0, 64, 64, GL_RG, GL_FLOAT, pairs.data());
            glTextureParameteri(noise_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(noise_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        glBindTextureUnit(kDeliot2023NoiseUnit, noise_);
    }

  private:
    GLuint noise_ = 0;  // RG32F 64 x 64, uploaded on first use
    unsigned frame_ = 0;
};

}  // namespace

std::vector<float> deliot2023_noise_pairs() {
    std::vector<float> pairs;
    pairs.reserve(64 * 64 * 2);
    for (const glm::vec2& v : deliot2023_noise_table()) {
        pairs.push_back(v.x);
        pairs.push_back(v.y);
    }
    return pairs;
}

const GpuModelHooks& deliot2023_gpu_hooks() {
    static const GpuModelHooks hooks{GlintModelId::Deliot2023, glue_path, kOptions,
                                     [] { return std::unique_ptr<GpuModelState>(new State); }};
    return hooks;
}

}  // namespace glintlab
