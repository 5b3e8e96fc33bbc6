#include "glintlab/realtime/glint_programs.h"

#include <algorithm>
#include <variant>

#include <epoxy/gl.h>

#include "glintlab/core/error.h"
#include "glintlab/glints/chermain2020/dictionary.h"
#include "glintlab/glints/deliot2023/deliot2023.h"
#include "glintlab/realtime/gpu_wang2020.h"
#include "glintlab/realtime/uniform_cache.h"
#include "glintlab/scene/scene.h"

namespace glintlab::gl {
namespace {

// The forward shader declares the shared glint uniforms used below:
// u_glint_ndf (NDF_BECKMANN / NDF_GGX), u_glint_alpha (alpha_x, alpha_y),
// u_glint_log_density, u_glint_seed.
constexpr const char* kSmoothGlue = R"(
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(D_Microfacet(u_glint_ndf, h, u_glint_alpha.x, u_glint_alpha.y));
}
float glint_masking(vec3 wo, vec3 wi, vec3 h) {
    return G2_SmithCorrelated(u_glint_ndf, wo, wi, u_glint_alpha.x, u_glint_alpha.y);
}
)";

// deliot2023 (papers/000): D_P of Eq. 3-4 with the hash uniforms (the CPU
// default; the 64x64 noise-table variant is a CPU speed experiment).
constexpr const char* kDeliot2023Glue = R"(
#include "glintlab/glints/deliot2023/deliot2023.glsl"
uniform float u_deliot2023_microfacet_roughness;
uniform float u_deliot2023_screen_space_scale;
uniform float u_deliot2023_density_randomization;
uniform bool u_deliot2023_original_defects;
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(deliot2023_ndf(h, fp, u_glint_ndf, u_glint_alpha.x, u_glint_alpha.y,
                               u_glint_log_density, u_glint_seed,
                               u_deliot2023_microfacet_roughness, u_deliot2023_screen_space_scale,
                               u_deliot2023_density_randomization, u_deliot2023_original_defects));
}
float glint_masking(vec3 wo, vec3 wi, vec3 h) {
    return G2_SmithCorrelated(u_glint_ndf, wo, wi, u_glint_alpha.x, u_glint_alpha.y);
}
)";

// zirr2016 (000's baseline [ZK16]).
constexpr const char* kZirr2016Glue = R"(
#include "glintlab/glints/zirr2016/zirr2016.glsl"
uniform float u_zirr2016_microfacet_roughness;
uniform float u_zirr2016_max_anisotropy;
uniform float u_zirr2016_screen_space_scale;
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(zirr2016_ndf(h, fp, u_glint_ndf, u_glint_alpha.x, u_glint_alpha.y,
                             u_glint_log_density, u_glint_seed, u_zirr2016_microfacet_roughness,
                             u_zirr2016_max_anisotropy, u_zirr2016_screen_space_scale));
}
float glint_masking(vec3 wo, vec3 wi, vec3 h) {
    return G2_SmithCorrelated(u_glint_ndf, wo, wi, u_glint_alpha.x, u_glint_alpha.y);
}
)";

// chermain2020 (papers/004): RGB D_P of Eq. 13 with the colour table, the
// dictionary through chermain2020.glsl's own sampler `chermain2020_dictionary`,
// V-cavity masking (004 Eq. 14-16) as GlintBxdf uses.
constexpr const char* kChermain2020Glue = R"(
#include "glintlab/glints/chermain2020/chermain2020.glsl"
uniform ivec3 u_chermain2020_dict_shape;  // n_levels, n_dists, table_size
uniform vec2 u_chermain2020_dict_range;   // alpha_dict, slope_max
uniform float u_chermain2020_relative_area;
uniform float u_chermain2020_max_anisotropy;
uniform float u_chermain2020_density_randomization;
uniform int u_chermain2020_colour_count;
uniform vec3 u_chermain2020_colours[CHERMAIN2020_MAX_COLOURS];
vec3 glint_ndf(vec3 h, Footprint fp) {
    Chermain2020Dict d;
    d.n_levels = u_chermain2020_dict_shape.x;
    d.n_dists = u_chermain2020_dict_shape.y;
    d.table_size = u_chermain2020_dict_shape.z;
    d.alpha_dict = u_chermain2020_dict_range.x;
    d.slope_max = u_chermain2020_dict_range.y;
    Chermain2020Colours colours;
    colours.count = u_chermain2020_colour_count;
    for (int i = 0; i < CHERMAIN2020_MAX_COLOURS; ++i) colours.table[i] = u_chermain2020_colours[i];
    return chermain2020_ndf_rgb(h, fp, d, u_glint_alpha.x, u_glint_alpha.y, u_glint_log_density,
                                u_glint_seed, u_chermain2020_relative_area,
                                u_chermain2020_max_anisotropy,
                                u_chermain2020_density_randomization, colours);
}
float glint_masking(vec3 wo, vec3 wi, vec3 h) { return G2_VCavity(wo, wi, h); }
)";

// kneiphof2025 (papers/003): the shared file's GLSL fetch functions read the
// CPU-prefiltered maps bound by realtime/kneiphof2025_gpu.h. Point and delta
// directional lights: deliot2023's D_P with the reused grid parameters (003
// Table 1: "identical to [DB23]"; kneiphof2025.cpp kneiphof2025_footprint_ndf).
// The environment and the area lights (sphere lights, sun cones) are shaded
// by the model itself, as kneiphof2025.cpp light_radiance does at the CPU's
// first hit: the forward shader calls glint_environment / glint_area_light
// when the glue defines GLINTLAB_GLINT_SHADES_ENVIRONMENT /
// GLINTLAB_GLINT_SHADES_AREA_LIGHTS.
constexpr const char* kKneiphof2025Glue = R"(
#include "glintlab/glints/kneiphof2025/kneiphof2025.glsl"
uniform int u_kneiphof2025_levels;         // K
uniform vec4 u_kneiphof2025_levels_a;      // L^(1..4) (Eq. 18)
uniform vec4 u_kneiphof2025_levels_b;      // L^(5..8)
uniform bool u_kneiphof2025_wang2020_style;
uniform float u_kneiphof2025_gamma_solid_angle;
uniform bool u_kneiphof2025_conditional;
uniform int u_kneiphof2025_smooth;  // KNEIPHOF2025_SMOOTH_*
uniform float u_kneiphof2025_microfacet_roughness;
uniform float u_kneiphof2025_screen_space_scale;
uniform float u_kneiphof2025_density_randomization;
uniform vec3 u_kneiphof2025_f0;             // kneiphof2025_f0(desc)
uniform float u_kneiphof2025_radiance_scale; // current environment scale / prefiltered one
float kneiphof2025_glue_alpha() { return clamp(u_glint_alpha.x, 1e-4f, 1.0f); }  // alpha_of
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(deliot2023_ndf(h, fp, NDF_GGX, u_glint_alpha.x, u_glint_alpha.y,
                               u_glint_log_density, u_glint_seed,
                               u_kneiphof2025_microfacet_roughness,
                               u_kneiphof2025_screen_space_scale,
                               u_kneiphof2025_density_randomization, false));
}
float glint_masking(vec3 wo, vec3 wi, vec3 h) {
    return G2_SmithCorrelated(u_glint_ndf, wo, wi, u_glint_alpha.x, u_glint_alpha.y);
}
#define GLINTLAB_GLINT_SHADES_ENVIRONMENT 1
// Eq. 17 under the environment (unshadowed, 003 §7); wo local, (t, b, n) the
// world shading frame; wr the mirror direction in world space.
vec3 glint_environment(vec3 wo, vec3 t, vec3 b, vec3 n, vec3 color, Footprint fp) {
    if (wo.z <= 0.0f) return vec3(0.0f);
    vec3 wr = (-wo.x) * t + (-wo.y) * b + wo.z * n;
    return u_kneiphof2025_radiance_scale *
           kneiphof2025_environment(n, wr, wo.z, kneiphof2025_glue_alpha(), u_kneiphof2025_f0,
                                    color, fp, u_glint_log_density, u_glint_seed,
                                    u_kneiphof2025_screen_space_scale,
                                    u_kneiphof2025_density_randomization, u_kneiphof2025_levels,
                                    u_kneiphof2025_levels_a, u_kneiphof2025_levels_b,
                                    u_kneiphof2025_wang2020_style ? KNEIPHOF2025_VARIANT_WANG2020
                                                                  : KNEIPHOF2025_VARIANT_OURS,
                                    u_kneiphof2025_gamma_solid_angle, u_kneiphof2025_conditional,
                                    u_kneiphof2025_smooth);
}
#define GLINTLAB_GLINT_SHADES_AREA_LIGHTS 1
// One area light (K = 1): a cone around the world direction `axis`; the
// caller multiplies by the shadow test towards the axis.
vec3 glint_area_light(vec3 axis, float cos_max, vec3 radiance, vec3 t, vec3 b, vec3 n, vec3 wo,
                      vec3 color, Footprint fp) {
    if (wo.z <= 0.0f) return vec3(0.0f);
    return kneiphof2025_area_light(axis, cos_max, radiance, t, b, n, wo, kneiphof2025_glue_alpha(),
                                   u_kneiphof2025_f0, color, fp, u_glint_log_density,
                                   u_glint_seed, u_kneiphof2025_microfacet_roughness,
                                   u_kneiphof2025_screen_space_scale,
                                   u_kneiphof2025_density_randomization);
}
)";

constexpr int kChermain2020DictionaryUnit = kFirstModelTextureUnit;
constexpr int kDeliot2023NoiseUnit = kFirstModelTextureUnit + 1;  // binding = 5 in the glue
static_assert(kDeliot2023NoiseUnit == 5);

}  // namespace

bool gpu_supports_model(GlintModelId model) {
    switch (model) {
        case GlintModelId::Smooth:
        case GlintModelId::Deliot2023:
        case GlintModelId::Zirr2016:
        case GlintModelId::Chermain2020:
        case GlintModelId::Wang2020:  // gpu_wang2020.h
        case GlintModelId::Kneiphof2025:
            return true;
        default:
            return false;
    }
}

// deliot2023's noise-texture variant: the fetch function the shared file
// calls under GLINTLAB_DELIOT2023_NOISE_TEXTURE, ahead of its include.
constexpr const char* kDeliot2023NoisePrefix = R"(
#define GLINTLAB_DELIOT2023_NOISE_TEXTURE 1
layout(binding = 5) uniform sampler2D u_deliot2023_noise;  // RG32F, 64 x 64
vec2 deliot2023_noise_fetch(uint cell_hash) {
    uint i = cell_hash % 4096u;
    return texelFetch(u_deliot2023_noise, ivec2(int(i % 64u), int(i / 64u)), 0).rg;
}
)";

std::string glint_model_glsl(GlintModelId model, bool noise_texture) {
    switch (model) {
        case GlintModelId::Smooth:
            return kSmoothGlue;
        case GlintModelId::Deliot2023:
            return noise_texture ? std::string(kDeliot2023NoisePrefix) + kDeliot2023Glue
                                 : std::string(kDeliot2023Glue);
        case GlintModelId::Zirr2016:
            return kZirr2016Glue;
        case GlintModelId::Chermain2020:
            return kChermain2020Glue;
        case GlintModelId::Wang2020:
            return wang2020_glsl();
        case GlintModelId::Kneiphof2025:
            return kKneiphof2025Glue;
        default:
            break;
    }
    const GlintModelInfo* info = find_glint_model(model);
    fail(
        "OpenGL renderer: glint model \"{}\" has no GPU implementation (GPU models: smooth, "
        "deliot2023, zirr2016, chermain2020, kneiphof2025, wang2020)",
        info != nullptr ? info->name : "?");
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
            // the wang2020 descriptor's check: isotropic Beckmann, alpha in
            // [0.02, 1] (the DPF roughness set, 001 §4.4), ln N <= 19.4.
            desc.ndf = NdfType::Beckmann;
            desc.alpha_x = desc.alpha_y = std::clamp(desc.alpha_x, 0.02f, 1.0f);
            desc.log_density = std::clamp(desc.log_density, 0.0f, 19.4f);
            desc.params = Wang2020Params{};
            break;
        case GlintModelId::Kneiphof2025:
            desc.base_albedo = glm::vec3(0.0f);  // it shades its lights itself: no base
            // 003 §7-8: the split-sum tables are isotropic GGX with alpha <= 1
            // (the kneiphof2025 descriptor's check rejects anything else).
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
