// `glintlab export` of wang2020 (its descriptor's GlintModelExport): the
// exported material's tables, which the renderer uploads as SSBOs and the
// export lays out in textures (wang2020_export_textures.glsl).
#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "glintlab/glints/model_export.h"
#include "glintlab/glints/wang2020/wang2020_model.h"
#include "glintlab/glints/wang2020/wang2020_shading.h"
#include "glintlab/scene/environment.h"

namespace glintlab {

void wang2020_export_material(GlintExportContext& ctx) {
    if (!ctx.resources) return;
    const GlintDesc& g = ctx.material;
    const std::shared_ptr<const EnvironmentMap>& env = ctx.environment;
    const std::string& env_source = ctx.environment_source;
    // The tables of the exported material (the default wang2020
    // material, or --scene's --material), under the environment if any
    // (--env, else the scene's): the arrays the renderer uploads as SSBOs,
    // laid out in textures WANG2020_TABLE_WIDTH (4096) texels wide.
    const auto model_tables = wang2020_model_for(g, env);
    constexpr size_t kWidth = 4096;  // WANG2020_TABLE_WIDTH
    auto table = [&]<class T>(const std::string& key, std::vector<T> values, int channels,
                              const std::string& format, const std::string& uniform,
                              const std::string& meaning) -> nlohmann::json& {
        const size_t elements = values.size() / static_cast<size_t>(channels);
        const size_t rows = std::max<size_t>(1, (elements + kWidth - 1) / kWidth);
        values.resize(rows * kWidth * static_cast<size_t>(channels), T(0));
        return ctx.resource(
            key, values,
            {{"uniform", uniform},
             {"format", format},
             {"width", kWidth},
             {"height", rows},
             {"elements", elements},
             {"filter", "nearest"},
             {"wrap", "clamp_to_edge"},
             {"mipmaps", false},
             {"meaning", meaning + "; element i at texel (i % 4096, i / 4096), texelFetch"}});
    };
    auto vec4s = [](const std::vector<glm::vec4>& v) {
        std::vector<float> out;
        for (const glm::vec4& e : v) out.insert(out.end(), {e.x, e.y, e.z, e.w});
        return out;
    };
    table("dpf", model_tables->dpf().values(), 1, "R32F", "u_wang2020_dpf_texture",
          "extracted DPF table P(i, o, gamma) (001 Eq. 6, 4.4)");
    nlohmann::json& prefilter =
        table("prefilter",
              model_tables->prefiltered() ? vec4s(model_tables->prefiltered()->data())
                                          : std::vector<float>(4, 0.0f),
              4, "RGBA32F", "u_wang2020_prefilter_texture",
              "prefiltered environment tables (001 Eqs. 16-17; one zero texel without --env)");
    if (model_tables->prefiltered()) prefilter["environment"] = env_source;
    {
        // Quadtree nodes {first_child, count_mask} as uint32 pairs (RG32UI).
        std::vector<uint32_t> pairs;
        for (const wang2020::QuadtreeNode& n : model_tables->quadtree().nodes()) {
            pairs.push_back(n.first_child);
            pairs.push_back(n.count_mask);
        }
        table("nodes", pairs, 2, "RG32UI", "u_wang2020_nodes_texture",
              "particle quadtree nodes {first_child, count_mask} (001 4.4)");
    }
    nlohmann::json& cone =
        table("cone",
              model_tables->particle_radiance_table()
                  ? vec4s(model_tables->particle_radiance_table()->data())
                  : std::vector<float>(4, 0.0f),
              4, "RGBA32F", "u_wang2020_cone_texture",
              "environment the particles reflect: point values or cone average L_gamma (micro "
              "per_particle mode; one zero texel "
              "otherwise)");
    const wang2020::DpfResolution& dr = model_tables->dpf().resolution();
    std::array<int, 4> pres{1, 1, 1, 1};
    if (model_tables->prefiltered()) {
        const wang2020::PrefilterResolution& pr = model_tables->prefiltered()->resolution();
        pres = {pr.theta_n, pr.phi_n, pr.theta_o, pr.phi_o};
    }
    const std::array<int, 2> cres =
        model_tables->particle_radiance_table()
            ? std::array<int, 2>{model_tables->particle_radiance_table()->width(),
                                 model_tables->particle_radiance_table()->height()}
            : std::array<int, 2>{1, 1};
    cone["uniforms"] = {
        {"u_wang2020_dpf_res", {dr.theta_i, dr.theta_o, dr.phi}},
        {"u_wang2020_prefilter_res", pres},
        {"u_wang2020_depth", model_tables->quadtree().depth()},
        {"u_wang2020_seed", model_tables->material().seed},
        {"u_wang2020_particles", static_cast<double>(model_tables->quadtree().particles())},
        {"u_wang2020_sigma", static_cast<double>(model_tables->sigma_o())},
        {"u_wang2020_micro", model_tables->micro_mode_index()},
        {"u_wang2020_cone_res", cres},
        {"u_wang2020_cos_gamma",
         std::cos(model_tables->material().gamma_deg * 3.14159265358979323846 / 180.0)},
        {"u_glint_alpha", {g.alpha_x, g.alpha_y}},
        {"u_glint_log_density", g.log_density},
        {"u_glint_seed", g.seed},
        // The prefiltered environment table integrates F(i·h) (Eq. 11's M,
        // docs/MODELS.md wang2020): the material's Fresnel is part of it.
        {"u_fresnel_mode", static_cast<int>(g.fresnel.mode)},
        {"u_fresnel_f0", {g.fresnel.f0.x, g.fresnel.f0.y, g.fresnel.f0.z}},
        {"u_fresnel_eta", {g.fresnel.eta.x, g.fresnel.eta.y, g.fresnel.eta.z}},
        {"u_fresnel_k", {g.fresnel.k.x, g.fresnel.k.y, g.fresnel.k.z}}};
    cone["note"] = fmt::format(
        "the tables are those of {} (uniforms above): a material with another alpha, "
        "density, seed, Fresnel or parameters needs its own tables (glintlab export --scene "
        "FILE --material NAME)",
        ctx.material_name.empty() ? std::string("the default wang2020 material")
                                  : fmt::format("material \"{}\"", ctx.material_name));
}

}  // namespace glintlab
