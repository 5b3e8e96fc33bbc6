// chermain2020 (004) on the GPU: the hooks of glints/gpu_model_hooks.h (glue
// chermain2020_gpu.glsl, the model's uniforms and the dictionary texture).
#include <variant>
#include <vector>

#include <epoxy/gl.h>

#include "glintlab/core/error.h"
#include "glintlab/gl/uniform_cache.h"
#include "glintlab/glints/chermain2020/dictionary.h"
#include "glintlab/glints/glint_desc.h"
#include "glintlab/glints/gpu_model_hooks.h"

namespace glintlab {
namespace {

constexpr int kDictionaryUnit = kFirstModelTextureUnit;

std::string glue_path(unsigned) {
    return "glintlab/glints/chermain2020/chermain2020_gpu.glsl";
}

class State final : public GpuModelState {
  public:
    ~State() override {
        if (dictionary_ != 0) glDeleteTextures(1, &dictionary_);
        if (filter_ != 0) glDeleteTextures(1, &filter_);
    }

    void prepare(unsigned program, gl::UniformCache& u, const GlintDesc& desc, const GpuFrame&,
                 unsigned) override {
        auto loc = [&](const char* name) { return u.location(program, name); };
        const auto& p = std::get<Chermain2020Params>(desc.params);
        const Dictionary& d = default_dictionary();
        glProgramUniform3i(program, loc("u_chermain2020_dict_shape"), d.params.n_levels,
                           d.params.n_dists, d.params.table_size);
        glProgramUniform2f(program, loc("u_chermain2020_dict_range"), d.params.alpha_dict,
                           d.slope_max);
        glProgramUniform1f(program, loc("u_chermain2020_relative_area"), p.relative_area);
        glProgramUniform1f(program, loc("u_chermain2020_max_anisotropy"), p.max_anisotropy);
        glProgramUniform1f(program, loc("u_chermain2020_density_randomization"),
                           p.density_randomization);
        glProgramUniform1i(program, loc("u_chermain2020_colour_count"), p.colour_count);
        glProgramUniform1i(program, loc("u_chermain2020_correlated"), p.slope_correlation ? 1 : 0);
        glProgramUniform3fv(program, loc("u_chermain2020_colours"),
                            static_cast<GLsizei>(p.colour_table.size()), &p.colour_table[0].x);
        glProgramUniform1i(program, loc("chermain2020_dictionary"), kDictionaryUnit);
        glProgramUniform1f(program, loc("u_chermain2020_ggaa_kernel"),
                           p.antialiasing ? p.antialiasing_kernel : 0.0f);
        if (p.antialiasing) {
            // The filter's texels hold the pairs too (.rg): one texture serves
            // both samplers, so anti-aliasing adds a channel, not a table.
            glProgramUniform1i(program, loc("chermain2020_dictionary_filter"), kDictionaryUnit);
            if (filter_ == 0) filter_ = upload(d, 3, chermain2020_dictionary_filter_texels(d));
            glBindTextureUnit(kDictionaryUnit, filter_);
        } else {
            if (dictionary_ == 0) dictionary_ = upload(d, 2, chermain2020_dictionary_pairs(d));
            glBindTextureUnit(kDictionaryUnit, dictionary_);
        }
    }

  private:
    // 004 §4.4-4.5: one row per (marginal, level), one texel per table
    // sample; read with texelFetch (the shared code interpolates itself).
    // RG32F: texel k holds samples k and k + 1 (0 past the row's end), the
    // two values one linear interpolation reads (chermain2020.glsl,
    // GLINTLAB_CHERMAIN2020_DICT_PAIRS). RGB32F adds the row's integral up
    // to sample k, for geometric glint anti-aliasing's box filter.
    GLuint upload(const Dictionary& d, int channels, const std::vector<float>& texels) {
        const int width = d.params.table_size;
        const int height = d.params.n_dists * d.params.n_levels;
        GLint max_size = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
        if (width > max_size || height > max_size)
            fail(
                "OpenGL renderer: the chermain2020 dictionary ({}x{} texels) exceeds "
                "GL_MAX_TEXTURE_SIZE = {}",
                width, height, max_size);
        GLuint texture = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &texture);
        glTextureStorage2D(texture, 1, channels == 3 ? GL_RGB32F : GL_RG32F, width, height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage2D(texture, 0, 0, 0, width, height, channels == 3 ? GL_RGB : GL_RG,
                            GL_FLOAT, texels.data());
        glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        return texture;
    }

    GLuint dictionary_ = 0;  // RG32F pairs, uploaded on first use
    GLuint filter_ = 0;      // RGB32F (pairs, integral), uploaded on first anti-aliased use
};

}  // namespace

const GpuModelHooks& chermain2020_gpu_hooks() {
    static const GpuModelHooks hooks{GlintModelId::Chermain2020, glue_path, {}, [] {
                                         return std::unique_ptr<GpuModelState>(new State);
                                     }};
    return hooks;
}

}  // namespace glintlab
