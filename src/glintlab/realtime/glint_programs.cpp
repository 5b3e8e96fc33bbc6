#include "glintlab/realtime/glint_programs.h"

#include <algorithm>
#include <variant>

#include <epoxy/gl.h>
#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/glints/chermain2020/dictionary.h"
#include "glintlab/glints/deliot2023/deliot2023.h"
#include "glintlab/glints/wang2020/wang2020_gpu.h"
#include "glintlab/realtime/uniform_cache.h"
#include "glintlab/scene/scene.h"

namespace glintlab::gl {
namespace {

constexpr int kChermain2020DictionaryUnit = kFirstModelTextureUnit;
constexpr int kDeliot2023NoiseUnit = kFirstModelTextureUnit + 1;  // binding = 5 in the glue
static_assert(kDeliot2023NoiseUnit == 5);  // deliot2023_noise_texture_gpu.glsl

}  // namespace

bool gpu_supports_model(GlintModelId model) {
    switch (model) {
        case GlintModelId::Smooth:
        case GlintModelId::Deliot2023:
        case GlintModelId::Zirr2016:
        case GlintModelId::Chermain2020:
        case GlintModelId::Wang2020:  // wang2020_gpu.h
        case GlintModelId::Kneiphof2025:
            return true;
        default:
            return false;
    }
}

std::string glint_model_glue_path(GlintModelId model, bool noise_texture) {
    switch (model) {
        case GlintModelId::Smooth:
            return "glintlab/glints/smooth_gpu.glsl";
        case GlintModelId::Deliot2023:
            return noise_texture ? "glintlab/glints/deliot2023/deliot2023_noise_texture_gpu.glsl"
                                 : "glintlab/glints/deliot2023/deliot2023_gpu.glsl";
        case GlintModelId::Zirr2016:
            return "glintlab/glints/zirr2016/zirr2016_gpu.glsl";
        case GlintModelId::Chermain2020:
            return "glintlab/glints/chermain2020/chermain2020_gpu.glsl";
        case GlintModelId::Wang2020:
            return "glintlab/glints/wang2020/wang2020_gpu.glsl";
        case GlintModelId::Kneiphof2025:
            return "glintlab/glints/kneiphof2025/kneiphof2025_gpu.glsl";
        default:
            break;
    }
    const GlintModelInfo* info = find_glint_model(model);
    fail(
        "OpenGL renderer: glint model \"{}\" has no GPU implementation (GPU models: smooth, "
        "deliot2023, zirr2016, chermain2020, kneiphof2025, wang2020)",
        info != nullptr ? info->name : "?");
}

std::string glint_model_glsl(GlintModelId model, bool noise_texture) {
    return fmt::format("#include \"{}\"\n", glint_model_glue_path(model, noise_texture));
}

GlintResources::GlintResources() = default;

GlintResources::~GlintResources() {
    if (chermain2020_dictionary_ != 0) glDeleteTextures(1, &chermain2020_dictionary_);
    if (deliot2023_noise_ != 0) glDeleteTextures(1, &deliot2023_noise_);
}

std::vector<float> deliot2023_noise_pairs() {
    std::vector<float> pairs;
    pairs.reserve(64 * 64 * 2);
    for (const glm::vec2& v : deliot2023_noise_table()) {
        pairs.push_back(v.x);
        pairs.push_back(v.y);
    }
    return pairs;
}

void GlintResources::bind(GlintModelId model, bool noise_texture) {
    if (model == GlintModelId::Deliot2023 && noise_texture) {
        if (deliot2023_noise_ == 0) {
            const std::vector<float> pairs = deliot2023_noise_pairs();
            glCreateTextures(GL_TEXTURE_2D, 1, &deliot2023_noise_);
            glTextureStorage2D(deliot2023_noise_, 1, GL_RG32F, 64, 64);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
            glTextureSubImage2D(deliot2023_noise_, 0, 0, 0, 64, 64, GL_RG, GL_FLOAT, pairs.data());
            glTextureParameteri(deliot2023_noise_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(deliot2023_noise_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        glBindTextureUnit(kDeliot2023NoiseUnit, deliot2023_noise_);
    }
    if (model != GlintModelId::Chermain2020) return;
    if (chermain2020_dictionary_ == 0) {
        // 004 §4.4-4.5: one row per (marginal, level), one texel per table
        // sample; read with texelFetch (the shared code interpolates itself).
        const Dictionary& d = default_dictionary();
        const int width = d.params.table_size;
        const int height = d.params.n_dists * d.params.n_levels;
        GLint max_size = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
        if (width > max_size || height > max_size)
            fail(
                "OpenGL renderer: the chermain2020 dictionary ({}x{} texels) exceeds "
                "GL_MAX_TEXTURE_SIZE = {}",
                width, height, max_size);
        glCreateTextures(GL_TEXTURE_2D, 1, &chermain2020_dictionary_);
        glTextureStorage2D(chermain2020_dictionary_, 1, GL_R32F, width, height);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage2D(chermain2020_dictionary_, 0, 0, 0, width, height, GL_RED, GL_FLOAT,
                            d.values.data());
        glTextureParameteri(chermain2020_dictionary_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(chermain2020_dictionary_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glBindTextureUnit(kChermain2020DictionaryUnit, chermain2020_dictionary_);
}

void set_glint_uniforms(unsigned program, UniformCache& u, const GlintDesc& desc) {
    auto loc = [&](const char* name) { return u.location(program, name); };
    switch (desc.model_id) {
        case GlintModelId::Deliot2023: {
            const auto& p = std::get<Deliot2023Params>(desc.params);
            glProgramUniform1f(program, loc("u_deliot2023_microfacet_roughness"),
                               p.microfacet_roughness);
            glProgramUniform1f(program, loc("u_deliot2023_screen_space_scale"),
                               p.screen_space_scale);
            glProgramUniform1f(program, loc("u_deliot2023_density_randomization"),
                               p.density_randomization);
            glProgramUniform1i(program, loc("u_deliot2023_original_defects"),
                               p.original_defects ? 1 : 0);
            break;
        }
        case GlintModelId::Zirr2016: {
            const auto& p = std::get<Zirr2016Params>(desc.params);
            glProgramUniform1f(program, loc("u_zirr2016_microfacet_roughness"),
                               p.microfacet_roughness);
            glProgramUniform1f(program, loc("u_zirr2016_max_anisotropy"), p.max_anisotropy);
            glProgramUniform1f(program, loc("u_zirr2016_screen_space_scale"), p.screen_space_scale);
            break;
        }
        case GlintModelId::Chermain2020: {
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
            glProgramUniform3fv(program, loc("u_chermain2020_colours"),
                                static_cast<GLsizei>(p.colour_table.size()), &p.colour_table[0].x);
            glProgramUniform1i(program, loc("chermain2020_dictionary"),
                               kChermain2020DictionaryUnit);
            break;
        }
        default:
            break;
    }
}

void reset_model_params(GlintDesc& desc, GlintModelId model) {
    const GlintModelInfo* info = find_glint_model(model);
    if (info == nullptr) fail("unknown glint model id {}", static_cast<int>(model));
    desc.model_id = model;
    desc.model = std::string(info->name);
    desc.model_params = nlohmann::json::object();
    switch (model) {
        case GlintModelId::Deliot2023:
            desc.params = Deliot2023Params{};
            break;
        case GlintModelId::Zirr2016:
            desc.params = Zirr2016Params{};
            break;
        case GlintModelId::Chermain2020:
            // 004 §4.3: the multiscale SDF is separable only for Beckmann
            // (the scene loader rejects chermain2020 with GGX).
            desc.ndf = NdfType::Beckmann;
            desc.params = Chermain2020Params{};
            break;
        case GlintModelId::Wang2020:
            desc.base_albedo = glm::vec3(0.0f);  // it shades its lights itself: no base
            // read_wang2020_params' domain: isotropic Beckmann, alpha in
            // [0.02, 1] (the DPF roughness set, 001 §4.4), ln N <= 19.4.
            desc.ndf = NdfType::Beckmann;
            desc.alpha_x = desc.alpha_y = std::clamp(desc.alpha_x, 0.02f, 1.0f);
            desc.log_density = std::clamp(desc.log_density, 0.0f, 19.4f);
            desc.params = Wang2020Params{};
            break;
        case GlintModelId::Kneiphof2025:
            desc.base_albedo = glm::vec3(0.0f);  // it shades its lights itself: no base
            // 003 §7-8: the split-sum tables are isotropic GGX with alpha <= 1
            // (read_kneiphof2025_params rejects anything else).
            desc.ndf = NdfType::GGX;
            desc.alpha_x = desc.alpha_y = std::min(desc.alpha_x, 1.0f);
            desc.params = Kneiphof2025Params{};
            break;
        default:
            desc.params = SmoothParams{};
            break;
    }
}

}  // namespace glintlab::gl
