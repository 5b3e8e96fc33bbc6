#include "glintlab/glints/kneiphof2025/kneiphof2025_gpu.h"

#include <cmath>
#include <set>
#include <variant>
#include <vector>

#include <epoxy/gl.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "glintlab/core/error.h"
#include "glintlab/gl/uniform_cache.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter_gpu.h"
#include "glintlab/scene/environment.h"
#include "glintlab/scene/scene.h"

namespace glintlab::gl {
namespace {

// Four channels [first, first + 4) of the interleaved CPU level (3 + K
// channels per texel; channels past the last are 0) into RGBA texels. For
// the radiance (first 0) the alpha is the sources channel `sources` (one
// float per texel; kneiphof2025.glsl kneiphof2025_radiance_sources_fetch).
std::vector<float> rgba_channels(const Kneiphof2025Level& l, int channels, int first,
                                 const Kneiphof2025Level* sources = nullptr) {
    const size_t n = static_cast<size_t>(l.width) * static_cast<size_t>(l.height);
    std::vector<float> out(n * 4, 0.0f);
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 4; ++c)
            if (first + c < channels && (first >= 3 || c < 3))
                out[i * 4 + c] = l.data[i * static_cast<size_t>(channels) + first + c];
        if (first == 0 && sources) out[i * 4 + 3] = sources->data[i];
    }
    return out;
}

// The sources' uniforms (kneiphof2025.glsl kneiphof2025_source): each
// map-frame direction turned by the current rotation about +y (world phi =
// map phi + rotation, as kneiphof2025_latlong_uv); count 0 without sources.
void set_source_uniforms(unsigned program, UniformCache& u, const Kneiphof2025Sources* sources,
                         float rotation_rad) {
    auto loc = [&](const char* name) { return u.location(program, name); };
    const int n = sources ? static_cast<int>(sources->directions.size()) : 0;
    glProgramUniform1i(program, loc("u_kneiphof2025_source_count"), n);
    if (n == 0) return;
    std::vector<glm::vec3> dirs;
    for (const glm::vec3& a : sources->map_directions)
        dirs.push_back(kneiphof2025_map_to_world(a, rotation_rad));
    glProgramUniform3fv(program, loc("u_kneiphof2025_source_direction"), n,
                        glm::value_ptr(dirs[0]));
    glProgramUniform3fv(program, loc("u_kneiphof2025_source_power"), n,
                        glm::value_ptr(sources->powers[0]));
    glProgramUniform1fv(program, loc("u_kneiphof2025_source_radius"), n, sources->radii.data());
    glProgramUniform3fv(program, loc("u_kneiphof2025_sources_color"), 1,
                        glm::value_ptr(sources->color));
}

}  // namespace

Kneiphof2025Resources::Kneiphof2025Resources() = default;
Kneiphof2025Resources::~Kneiphof2025Resources() = default;

const Kneiphof2025Resources::Maps& Kneiphof2025Resources::maps_for(
    const std::shared_ptr<const EnvironmentMap>& map, int levels, float black_level) {
    Maps& m = maps_[{map.get(), levels, black_level}];
    if (m.env && m.owner == map) return m;
    m.owner = map;
    m.env = kneiphof2025_environment_for(map, levels, black_level);
    const Kneiphof2025Environment& env = *m.env;
    const auto& mips = env.mips();
    const int w = mips[0].width, h = mips[0].height, layers = static_cast<int>(mips.size());
    for (const Kneiphof2025Level& l : mips)
        if (l.width != w || l.height != h)
            fail("kneiphof2025 (GPU): prefiltered levels of unequal size ({}x{} vs {}x{})", l.width,
                 l.height, w, h);
    m.radiance = make_latlong_array(w, h, layers);
    m.weights_a = make_latlong_array(w, h, layers);
    m.weights_b = make_latlong_array(w, h, layers);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    const int C = env.channels();
    for (int i = 0; i < layers; ++i) {
        const Kneiphof2025Level& l = mips[static_cast<size_t>(i)];
        // RGB radiance; the weights of levels 1-4 (channels 3-6) and 5-8 (7-10).
        const std::vector<float> rad =
            rgba_channels(l, C, 0, &env.source_mips()[static_cast<size_t>(i)]);
        const std::vector<float> wa = rgba_channels(l, C, 3);
        const std::vector<float> wb = rgba_channels(l, C, 7);
        glTextureSubImage3D(m.radiance.get(), 0, 0, 0, i, w, h, 1, GL_RGBA, GL_FLOAT, rad.data());
        glTextureSubImage3D(m.weights_a.get(), 0, 0, 0, i, w, h, 1, GL_RGBA, GL_FLOAT, wa.data());
        glTextureSubImage3D(m.weights_b.get(), 0, 0, 0, i, w, h, 1, GL_RGBA, GL_FLOAT, wb.data());
    }
    return m;
}

void Kneiphof2025Resources::prepare(unsigned program, UniformCache& u, const Scene& scene,
                                    const GlintDesc& desc, float environment_scale,
                                    float environment_rotation_rad) {
    const auto& k = std::get<Kneiphof2025Params>(desc.params);
    auto loc = [&](const char* name) { return u.location(program, name); };
    if (!dfg_) {
        // (A, B, E_D / D_H) at (cos_o, sqrt(alpha)) texel centres: the CPU
        // table itself (lookup at a texel centre returns the entry exactly),
        // bilinear with clamped borders like Kneiphof2025DfgLut::lookup.
        constexpr int n = Kneiphof2025DfgLut::kSize;
        const std::vector<float> rgba = Kneiphof2025DfgLut::get().rgba_texture();
        dfg_ = make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(dfg_.get(), 1, GL_RGBA32F, n, n);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage2D(dfg_.get(), 0, 0, 0, n, n, GL_RGBA, GL_FLOAT, rgba.data());
        glTextureParameteri(dfg_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(dfg_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(dfg_.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(dfg_.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glBindTextureUnit(kKneiphof2025DfgUnit, dfg_.get());
    glProgramUniform1i(program, loc("kneiphof2025_dfg_lut"), kKneiphof2025DfgUnit);
    glProgramUniform1i(program, loc("kneiphof2025_radiance_layers"), kKneiphof2025RadianceUnit);
    glProgramUniform1i(program, loc("kneiphof2025_weights_layers_a"), kKneiphof2025WeightsAUnit);
    glProgramUniform1i(program, loc("kneiphof2025_weights_layers_b"), kKneiphof2025WeightsBUnit);

    // Parameters of the environment shading (kneiphof2025.cpp
    // kneiphof2025_environment_radiance) and of the grid (point, sun, sphere lights).
    glProgramUniform1i(program, loc("u_kneiphof2025_levels"), k.levels);
    glProgramUniform1i(program, loc("u_kneiphof2025_wang2020_style"),
                       k.variant == Kneiphof2025Params::Variant::Wang2020Style ? 1 : 0);
    glProgramUniform1f(program, loc("u_kneiphof2025_gamma_solid_angle"),
                       2.0f * glm::pi<float>() * (1.0f - std::cos(glm::radians(k.gamma_deg))));
    glProgramUniform1i(program, loc("u_kneiphof2025_conditional"), k.conditional_gaussian ? 1 : 0);
    glProgramUniform1i(program, loc("u_kneiphof2025_smooth"), kneiphof2025_smooth_mode(k));
    glProgramUniform1f(program, loc("u_kneiphof2025_microfacet_roughness"), k.microfacet_roughness);
    glProgramUniform1i(program, loc("u_kneiphof2025_light_sized_grid"),
                       k.light_sized_area_grid ? 1 : 0);
    glProgramUniform1f(program, loc("u_kneiphof2025_screen_space_scale"), k.screen_space_scale);
    glProgramUniform1f(program, loc("u_kneiphof2025_density_randomization"),
                       k.density_randomization);
    const glm::vec3 f0 = kneiphof2025_f0(desc);
    glProgramUniform3fv(program, loc("u_kneiphof2025_f0"), 1, glm::value_ptr(f0));

    if (scene.environment < 0) return;  // no environment: the maps are not read
    const auto& light =
        std::get<EnvironmentLight>(scene.lights[static_cast<size_t>(scene.environment)]);
    if (!light.map) fail("kneiphof2025: environment light without a map");
    glProgramUniform1f(program, loc("kneiphof2025_env_rotation"), environment_rotation_rad);
    if (dynamic_) {
        const auto it = gpu_prefilters_.find({k.levels, k.black_level, full_resolution_});
        if (it == gpu_prefilters_.end())
            fail("kneiphof2025: dynamic environment without begin_frame() for this material");
        const Kneiphof2025GpuPrefilter& g = *it->second;
        const auto& L = g.radiance_levels();
        glProgramUniform4f(program, loc("u_kneiphof2025_levels_a"), L[0], L[1], L[2], L[3]);
        glProgramUniform4f(program, loc("u_kneiphof2025_levels_b"), L[4], L[5], L[6], L[7]);
        glProgramUniform1f(program, loc("kneiphof2025_last_layer"),
                           static_cast<float>(g.layers() - 1));
        glProgramUniform1f(program, loc("u_kneiphof2025_radiance_scale"),
                           1.0f);  // prefiltered at the current scale
        // No sources channel in the GPU prefilter's arrays (alpha 0):
        // "lobe_sun" reads the lobe with the sources in the maps there
        // (docs/MODELS.md).
        set_source_uniforms(program, u, nullptr, environment_rotation_rad);
        glBindTextureUnit(kKneiphof2025RadianceUnit, g.radiance());
        glBindTextureUnit(kKneiphof2025WeightsAUnit, g.weights_a());
        glBindTextureUnit(kKneiphof2025WeightsBUnit, g.weights_b());
        return;
    }
    const Maps& m = maps_for(light.map, k.levels, k.black_level);
    const auto& L = m.env->radiance_levels();
    glProgramUniform4f(program, loc("u_kneiphof2025_levels_a"), L[0], L[1], L[2], L[3]);
    glProgramUniform4f(program, loc("u_kneiphof2025_levels_b"), L[4], L[5], L[6], L[7]);
    glProgramUniform1f(program, loc("kneiphof2025_last_layer"),
                       static_cast<float>(m.env->mips().size() - 1));
    const float baked = light.map->scale();
    glProgramUniform1f(program, loc("u_kneiphof2025_radiance_scale"),
                       baked != 0.0f ? environment_scale / baked : 0.0f);
    set_source_uniforms(program, u, &m.env->sources(), environment_rotation_rad);
    glBindTextureUnit(kKneiphof2025RadianceUnit, m.radiance.get());
    glBindTextureUnit(kKneiphof2025WeightsAUnit, m.weights_a.get());
    glBindTextureUnit(kKneiphof2025WeightsBUnit, m.weights_b.get());
}

void Kneiphof2025Resources::begin_frame(const Scene& scene, unsigned environment, int width,
                                        int height, float scale) {
    if (!dynamic_ || scene.environment < 0) return;
    std::set<std::pair<int, float>> done;  // one run per (K, black level) and frame
    for (const MaterialDesc& m : scene.materials) {
        if (m.type != MaterialDesc::Type::Glint || m.glint.model_id != GlintModelId::Kneiphof2025)
            continue;
        const auto& k = std::get<Kneiphof2025Params>(m.glint.params);
        if (!done.insert({k.levels, k.black_level}).second) continue;
        auto& g = gpu_prefilters_[{k.levels, k.black_level, full_resolution_}];
        if (!g) {
            // The CPU prefilter's defaults (resolution, layers, kernel samples).
            Kneiphof2025PrefilterOptions o;
            o.levels = k.levels;
            o.black_level = k.black_level;
            g = std::make_unique<Kneiphof2025GpuPrefilter>(
                o, full_resolution_ ? Kneiphof2025GpuPrefilter::Resolution::Full
                                    : Kneiphof2025GpuPrefilter::Resolution::Reduced);
        }
        g->run(environment, width, height, scale);
    }
}

}  // namespace glintlab::gl
