// `glintlab export` of kneiphof2025 (its descriptor's GlintModelExport): the
// DFG table, the environment's prefiltered maps (003 Eq. 11, 19-21) with the
// bright sources the prefilter takes out, and the uniforms the host derives from the
// parameters (kneiphof2025_gpu.cpp computes the same for the renderer).
#include <cmath>

#include "glintlab/glints/kneiphof2025/kneiphof2025.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"
#include "glintlab/glints/model_export.h"
#include "glintlab/scene/environment.h"

namespace glintlab {

void kneiphof2025_export_material(GlintExportContext& ctx) {
    const GlintDesc& g = ctx.material;
    const std::shared_ptr<const EnvironmentMap>& env = ctx.environment;
    const std::string& env_source = ctx.environment_source;
    // kneiphof2025's bright sources (the "lobe_sun" smooth term): found by
    // the prefilter of the exported environment; none without one.
    Kneiphof2025Sources sources;
    if (ctx.resources) {
        constexpr int n = Kneiphof2025DfgLut::kSize;
        const std::vector<float> rgba = Kneiphof2025DfgLut::get().rgba_texture();
        ctx.resource(
            "dfg", rgba,
            {{"uniform", "kneiphof2025_dfg_lut"},
             {"format", "RGBA32F"},
             {"width", n},
             {"height", n},
             {"filter", "linear"},
             {"wrap", "clamp_to_edge"},
             {"mipmaps", false},
             {"meaning",
              "(A, B, E_D / D_H, 0) of isotropic GGX at (cos_o, sqrt(alpha)) texel centres "
              "(003 Eq. 11, 21)"}});
        if (env) {
            // The renderer's prefilter options with the material's K and
            // black level (kneiphof2025_gpu.cpp does the same).
            const auto& kp = std::get<Kneiphof2025Params>(g.params);
            Kneiphof2025PrefilterOptions po;
            po.levels = kp.levels;
            po.black_level = kp.black_level;
            const auto cached = Kneiphof2025Environment::load_or_build(*env, po);
            const Kneiphof2025Environment& pre = *cached;
            const int layers = static_cast<int>(pre.mips().size());
            const int w = pre.mips()[0].width, h = pre.mips()[0].height;
            const int channels = pre.channels();
            sources = pre.sources();
            std::vector<float> rad, wa, wb;
            for (size_t i = 0; i < pre.mips().size(); ++i) {
                const Kneiphof2025Level& l = pre.mips()[i];
                const Kneiphof2025Level& src_level = pre.source_mips()[i];
                // The data's rows run from v = 0 (zenith) down; a texture's
                // row 0 is t = 0, the same v: no flip. The radiance's alpha
                // is the sources channel (kneiphof2025_gpu.cpp does the same).
                for (int p = 0; p < l.width * l.height; ++p) {
                    const float* src = &l.data[static_cast<size_t>(p) * channels];
                    for (int c = 0; c < 4; ++c) {
                        rad.push_back(c < 3 ? src[c] : src_level.data[static_cast<size_t>(p)]);
                        wa.push_back(3 + c < channels ? src[3 + c] : 0.0f);
                        wb.push_back(7 + c < channels ? src[7 + c] : 0.0f);
                    }
                }
            }
            const nlohmann::json common = {{"format", "RGBA32F"},
                                           {"target", "2D_ARRAY"},
                                           {"width", w},
                                           {"height", h},
                                           {"layers", layers},
                                           {"filter", "linear"},
                                           {"wrap", "repeat_s_clamp_t"},
                                           {"mipmaps", false},
                                           {"environment", env_source}};
            nlohmann::json r = common;
            r["uniform"] = "kneiphof2025_radiance_layers";
            r["meaning"] =
                "prefiltered radiance (003 Eq. 11) in rgb and, in alpha, the luminance of the "
                "environment's bright sources above their surroundings alone, prefiltered by "
                "the same kernel (0 without sources; the lobe_sun smooth term, "
                "u_kneiphof2025_source* uniforms), layer i: sqrt(alpha) = i / (layers - 1), "
                "lat-long, v = 0 at the zenith";
            ctx.resource("env_radiance", rad, r);
            r = common;
            r["uniform"] = "kneiphof2025_weights_layers_a";
            r["meaning"] = "prefiltered fuzzy indicators w^(1..4) (003 Eq. 19-21)";
            ctx.resource("env_weights_a", wa, r);
            r = common;
            r["uniform"] = "kneiphof2025_weights_layers_b";
            r["meaning"] = "prefiltered fuzzy indicators w^(5..8) (003 Eq. 19-21)";
            nlohmann::json& last = ctx.resource("env_weights_b", wb, r);
            const auto& L = pre.radiance_levels();
            last["uniforms"] = {{"u_kneiphof2025_levels_a", {L[0], L[1], L[2], L[3]}},
                                {"u_kneiphof2025_levels_b", {L[4], L[5], L[6], L[7]}},
                                {"kneiphof2025_last_layer", static_cast<float>(layers - 1)},
                                {"u_kneiphof2025_radiance_scale", 1.0f},
                                {"levels_K", pre.levels()}};
        }
    }

    // Uniforms the host derives from parameters (the renderer's GPU hooks
    // compute them in C++), with how to compute them.
    auto v3 = [](const glm::vec3& v) { return nlohmann::json{v.x, v.y, v.z}; };
    auto v3s = [&](const std::vector<glm::vec3>& vs) {
        nlohmann::json a = nlohmann::json::array();
        for (const glm::vec3& v : vs) a.push_back(v3(v));
        return a;
    };
    const Kneiphof2025Params& k = std::get<Kneiphof2025Params>(g.params);
    const glm::vec3 f0 = kneiphof2025_f0(g);
    ctx.derived_uniforms = {
        {{"uniform", "u_kneiphof2025_wang2020_style"},
         {"value", k.variant == Kneiphof2025Params::Variant::Wang2020Style},
         {"from", "variant == \"wang2020_style\""}},
        {{"uniform", "u_kneiphof2025_conditional"},
         {"value", k.conditional_gaussian},
         {"from", "gaussian == \"conditional\""}},
        {{"uniform", "u_kneiphof2025_light_sized_grid"},
         {"value", k.light_sized_area_grid},
         {"from", "area_grid == \"light_size\""}},
        {{"uniform", "u_kneiphof2025_gamma_solid_angle"},
         {"value", 2.0 * 3.14159265358979323846 *
                       (1.0 - std::cos(k.gamma_deg * 3.14159265358979323846 / 180.0))},
         {"from", "2 pi (1 - cos(gamma_deg))"}},
        {{"uniform", "u_kneiphof2025_smooth"},
         {"value", kneiphof2025_smooth_mode(k)},
         {"from",
          "smooth: \"as_published\" or \"split_sum\" -> 0, \"lobe\" -> 1, "
          "\"lobe_sun\" -> 2 (KNEIPHOF2025_SMOOTH_*)"}},
        {{"uniform", "u_kneiphof2025_f0"},
         {"value", {f0.x, f0.y, f0.z}},
         {"from",
          "Schlick F0 of the material's Fresnel: none -> 1, schlick -> f0, conductor / "
          "dielectric -> their Fresnel at normal incidence"}},
        {{"uniform", "u_kneiphof2025_radiance_scale"},
         {"value", 1.0},
         {"from", "current environment scale / the scale the maps were prefiltered at"}},
        {{"uniform", "kneiphof2025_env_rotation"},
         {"value", 0.0},
         {"from", "environment rotation about +y, radians"}},
        // The bright sources the prefilter took out of the exported maps
        // (Kneiphof2025Sources; read by "lobe_sun", with the radiance
        // array's alpha): count 0 without any (no --env, or a map without
        // a source), and for maps prefiltered by the compute passes, which
        // have no sources channel.
        {{"uniform", "u_kneiphof2025_source_count"},
         {"value", sources.directions.size()},
         {"from", "the number of entries of the u_kneiphof2025_source_* arrays (at most 16)"}},
        {{"uniform", "u_kneiphof2025_source_direction"},
         {"value", v3s(sources.map_directions)},
         {"from",
          "each direction in the map's frame (value: rotation 0) turned about +y by the "
          "environment rotation r: (x cos r - z sin r, y, z cos r + x sin r)"}},
        {{"uniform", "u_kneiphof2025_source_power"},
         {"value", v3s(sources.powers)},
         {"from",
          "each direction's RGB power (radiance above the surroundings x solid angle) at the "
          "scale the maps were prefiltered at"}},
        {{"uniform", "u_kneiphof2025_source_radius"},
         {"value", sources.radii},
         {"from", "the angular radius (radians) of the solid angle each direction stands for"}},
        {{"uniform", "u_kneiphof2025_sources_color"},
         {"value", v3(sources.color)},
         {"from",
          "sum of the powers / its luminance: the radiance alpha times it is the sources' "
          "RGB"}},
        {{"uniform", "black_level"},
         {"value", k.black_level},
         {"from",
          "not a uniform: the prefilter's black level (the --env maps use the "
          "default)"}}};
}

}  // namespace glintlab
