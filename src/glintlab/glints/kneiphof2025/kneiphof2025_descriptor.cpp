// kneiphof2025's descriptor (glint_model_descriptor.h): environment, sphere
// and sun-like directional lights by its own counting (003 Eq. 17; K = 1 area
// lights, 003 Eq. 6-9); point and delta directional lights through
// deliot2023's D_P (003 Table 1).
#include <algorithm>

#include "glintlab/core/json_reader.h"
#include "glintlab/glints/facet_extent.h"
#include "glintlab/glints/glint_model_descriptor.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025.h"

namespace glintlab {
namespace {

// 003 §7-8: the split-sum tables are isotropic GGX. A roughness map is one
// texture for both axes (read_roughness_or_textures gives both axes the same
// input); an [alpha_x, alpha_y] pair with a texture in it is anisotropic.
void check_kneiphof2025(JsonObject& block, GlintDesc& desc) {
    const bool anisotropic_map =
        desc.textures != nullptr && desc.textures->alpha_x_sq != desc.textures->alpha_y_sq;
    if (desc.ndf != NdfType::GGX || desc.alpha_x != desc.alpha_y || desc.alpha_x > 1.0f ||
        anisotropic_map)
        block.error("",
                    "kneiphof2025 needs an isotropic GGX material with roughness <= 1 "
                    "(\"ndf\": \"ggx\", one roughness value or one roughness texture; "
                    "003 §7-8: the split-sum tables are isotropic GGX)");
}

// 003 §7-8: the split-sum tables are isotropic GGX with alpha <= 1 (what
// check_kneiphof2025 requires).
void fit_kneiphof2025(GlintDesc& desc) {
    desc.ndf = NdfType::GGX;
    desc.alpha_x = desc.alpha_y = std::min(desc.alpha_x, 1.0f);
}

// compare (facet_extent.h): the point-light grid's R of 000 Eq. 4, and the
// wang2020_style variant's cone (the same definition as explicit's gamma).
std::string match_kneiphof2025_facet_cone(GlintDesc& desc, double gamma_rad) {
    std::string text = set_facet_extent_param(desc, "microfacet_roughness",
                                              microfacet_roughness_for_cone(desc, gamma_rad));
    if (std::get<Kneiphof2025Params>(desc.params).variant ==
        Kneiphof2025Params::Variant::Wang2020Style)
        text += ", " + set_facet_cone_param(desc, "gamma_deg", gamma_rad);
    return text;
}

}  // namespace

const GpuModelHooks& kneiphof2025_gpu_hooks();               // kneiphof2025/kneiphof2025_gpu*.cpp
void kneiphof2025_export_material(GlintExportContext& ctx);  // kneiphof2025/kneiphof2025_export.cpp

GlintModelDescriptor kneiphof2025_descriptor() {
    namespace gp = glint_param;
    using P = Kneiphof2025Params;
    GlintModelDescriptor d = make_glint_model_descriptor<P>(
        GlintModelId::Kneiphof2025, "kneiphof2025",
        "image-based lighting of glints, multinomial over K radiance levels (Kneiphof & Klein "
        "2025)",
        {GlintLightType::Point, GlintLightType::Directional, GlintLightType::Sphere,
         GlintLightType::Environment});
    d.citations = {{"003", "Kneiphof, Klein", 2025, "Computer Graphics Forum 44(4) (EGSR 2025)",
                    "Real-Time Image-Based Lighting of Glints"}};
    d.set_gpu_hooks(GLINTLAB_GPU_HOOKS(kneiphof2025_gpu_hooks));
    GlintModelExport& e = d.set_export("glintlab/glints/kneiphof2025/kneiphof2025_gpu.glsl",
                                       GLINTLAB_EXPORT_HOOK(kneiphof2025_export_material));
    e.compute = {"glintlab/glints/kneiphof2025/kneiphof2025_prefilter_base.comp.glsl",
                 "glintlab/glints/kneiphof2025/kneiphof2025_prefilter_partition.comp.glsl",
                 "glintlab/glints/kneiphof2025/kneiphof2025_prefilter_reduce.comp.glsl",
                 "glintlab/glints/kneiphof2025/kneiphof2025_prefilter_filter.comp.glsl"};
    d.params = {
        gp::integer("levels", &P::levels, 4, 8, "",
                    "K radiance levels of the environment partition (003 §4-5)", {4, 8}),
        // The paper suggests [1e-5, 1e-2]; [1e-8, 1] is accepted.
        gp::number("black_level", &P::black_level, 1e-8, 1.0, "",
                   "l of 003 §5: the dimmest non-zero level is at least this luminance",
                   GlintParamUi::Decades),
        gp::choice("variant", &P::variant,
                   {{"kneiphof2025", P::Variant::Kneiphof2025},
                    {"wang2020_style", P::Variant::Wang2020Style}},
                   "003 Fig. 8: p from the environment's partition, or from a fixed cone of "
                   "half-angle gamma_deg"),
        gp::choice("gaussian", &P::conditional_gaussian,
                   {{"conditional", true}, {"algorithm1", false}},
                   "Gaussian of the dual-gated law (environment) and of the single-gated law "
                   "(lights): conditional moments (unbiased), or 003 Algorithm 1 / Eq. 23 as "
                   "published"),
        gp::choice("smooth", &P::smooth,
                   {{"lobe_sun", P::Smooth::LobeSun},
                    {"as_published", P::Smooth::SplitSum},
                    {"split_sum", P::Smooth::SplitSum},
                    {"lobe", P::Smooth::Lobe}},
                   "smooth radiance the glint factor multiplies (Eq. 11): the filtered "
                   "reflection lobe without the map's bright sources plus the sources as 16 "
                   "directions, 003's split sum (split_sum: its old name), or the lobe with "
                   "the sources in the maps"),
        // Cone half-angle of the wang2020-style probability.
        gp::number("gamma_deg", &P::gamma_deg, 0.01, 45.0, "deg",
                   "cone half-angle of the wang2020_style probability", GlintParamUi::Log),
        // Same ranges as deliot2023's block.
        gp::number("microfacet_roughness", &P::microfacet_roughness, 1e-4, 1.0, "",
                   "deliot2023's R for point, directional and sphere lights", GlintParamUi::Log),
        gp::choice("area_grid", &P::light_sized_area_grid,
                   {{"light_size", true}, {"as_published", false}},
                   "angular cell size of sphere lights' and sun cones' glints: R widened by the "
                   "light's half-vector cone (glints live as long as a facet reflects the "
                   "light), or R as published"),
        gp::number("screen_space_scale", &P::screen_space_scale, 0.5, 8.0, "px",
                   "deliot2023's minimum glint size in pixels"),
        gp::number("density_randomization", &P::density_randomization, 0.0, 50.0, "",
                   "deliot2023's std-dev of the per-cell jitter of ln(density)"),
    };
    // The maps, the split-sum tables and the grids read alpha and ln N per
    // hit: roughness and density maps, and alpha widened by a normal map or
    // a curved surface, reach every light path. The environment and area
    // lights take the isotropic alpha of the same total slope variance
    // (kneiphof2025_isotropic_alpha); point and delta directional lights,
    // deliot2023's D_P, the widened (alpha_x, alpha_y) and the slopes'
    // correlation.
    d.reads_slope_correlation = [](const GlintDesc&) { return true; };
    d.check = check_kneiphof2025;
    d.fit_material = fit_kneiphof2025;
    d.shades_light = GLINTLAB_SHADES_LIGHT_HOOK(kneiphof2025_shades_light);
    d.light_radiance = GLINTLAB_LIGHT_RADIANCE_HOOK(kneiphof2025_light_radiance);
    d.match_facet_cone = match_kneiphof2025_facet_cone;
    d.validation = {"kneiphof2025"};  // run by the research library (validation_suites.h)
    return d;
}

}  // namespace glintlab
