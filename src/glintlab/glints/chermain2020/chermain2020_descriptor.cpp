// chermain2020's descriptor (glint_model_descriptor.h): point and directional
// lights only (D_P is evaluated at one half vector); Beckmann only.
#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/glints/chermain2020/dictionary.h"
#include "glintlab/glints/facet_extent.h"
#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {
namespace {

// The material must be Beckmann (004 §4.3: the multiscale SDF is a product
// of two marginals; GGX is not separable); "colours" is a list of RGB tints.
void check_chermain2020(JsonObject& block, GlintDesc& desc) {
    if (desc.ndf != NdfType::Beckmann)
        fail(
            "{}: {}: chermain2020 supports only \"ndf\": \"beckmann\" (its multiscale SDF is a "
            "product of two marginals, 004 §4.3; GGX is not separable)",
            block.file(), block.path());
    Chermain2020Params& p = std::get<Chermain2020Params>(desc.params);
    // "colours": [[r, g, b], ...], 1 to 8 tints in [0, 1] (004 §7.1 colour table).
    if (const nlohmann::json* colours = block.raw("colours")) {
        const std::string where = fmt::format("{}: {}/colours", block.file(), block.path());
        if (!colours->is_array() || colours->empty() || colours->size() > p.colour_table.size())
            fail("{}: expected an array of 1 to {} RGB colours [r, g, b] with components in [0, 1]",
                 where, p.colour_table.size());
        p.colour_count = static_cast<int>(colours->size());
        for (size_t i = 0; i < colours->size(); ++i)
            p.colour_table[i] =
                json_to_vec3((*colours)[i], fmt::format("{}/{}", where, i), 0.0f, 1.0f);
    }
}

// 004 §4.3: the multiscale SDF is separable only for Beckmann.
void fit_chermain2020(GlintDesc& desc) {
    desc.ndf = NdfType::Beckmann;
}

// compare (facet_extent.h): the dictionary's Gaussian lobes (std-dev
// lobe_sigma in the dictionary's slopes, 004 §4.4) scaled to the material's
// slopes by alpha / alpha_dict (Alg. 3's S_alpha): the method fixes them.
double chermain2020_facet_cone(const GlintDesc& desc) {
    const DictionaryParams dict;  // default_dictionary()'s parameters
    const double scale = double(dict.lobe_sigma) / double(dict.alpha_dict);
    return cone_for_gaussian_slope_lobe(scale * desc.alpha_x, scale * desc.alpha_y);
}

}  // namespace

const GpuModelHooks& chermain2020_gpu_hooks();               // chermain2020/chermain2020_gpu*.cpp
void chermain2020_export_material(GlintExportContext& ctx);  // chermain2020/chermain2020_export.cpp

GlintModelDescriptor chermain2020_descriptor() {
    namespace gp = glint_param;
    using P = Chermain2020Params;
    GlintModelDescriptor d = make_glint_model_descriptor<P>(
        GlintModelId::Chermain2020, "chermain2020",
        "multiscale SDF dictionary over a MIP hierarchy (Chermain et al. 2020)",
        {GlintLightType::Point, GlintLightType::Directional});
    d.citations = {{"004", "Chermain, Sauvage, Dischler, Dachsbacher", 2020,
                    "Computer Graphics Forum 39(7) (Pacific Graphics 2020)",
                    "Procedural Physically based BRDF for Real-Time Rendering of Glints"}};
    d.set_gpu_hooks(GLINTLAB_GPU_HOOKS(chermain2020_gpu_hooks));
    d.set_export("glintlab/glints/chermain2020/chermain2020_gpu.glsl",
                 GLINTLAB_EXPORT_HOOK(chermain2020_export_material))
        .defines = {"GLINTLAB_GLINT_VIEW_DIFFERENTIALS", "GLINTLAB_CHERMAIN2020_ONE_TABLE"};
    d.params = {
        gp::number("relative_area", &P::relative_area, 0.0, 1.0, "",
                   "beta (004 §7.1): fraction of cells that carry facets"),
        // gamma < 1 is meaningless (major >= minor); above 32 the per-level
        // cell walk is capped at 64 cells per axis.
        gp::number("max_anisotropy", &P::max_anisotropy, 1.0, 32.0, "",
                   "gamma (004 §7.1): largest major/minor ratio of the footprint"),
        // zeta in dictionary levels; 8 levels is a factor 4^8 in density already.
        gp::number("density_randomization", &P::density_randomization, 0.0, 8.0, "levels",
                   "zeta (004 §7.1, Alg. 3 line 8): std-dev of the distribution LOD"),
        gp::choice("slope_correlation", &P::slope_correlation,
                   {{"chermain2021", true}, {"none", false}},
                   "a normal map's or curved surface's slope correlation shears the target NDF "
                   "(Chermain et al. 2021, Eq. 18), or is dropped (004)"),
        gp::choice("antialiasing", &P::antialiasing, {{"chermain2021", true}, {"none", false}},
                   "geometric glint anti-aliasing: each cell's marginals box-filtered over the "
                   "half vector's slope sweep across the pixel (Chermain et al. 2021, §4), or "
                   "read at the pixel centre (004)"),
        // Their KernelSize, a user scale of the sweep: below 1/4 the filter is
        // narrower than the sweep's quarter, above 4 it blurs glints of
        // neighbouring pixels' half vectors into this one.
        gp::number("antialiasing_kernel", &P::antialiasing_kernel, 0.25, 4.0, "",
                   "the box's width in the half vector's slope sweep per pixel step "
                   "(Chermain et al. 2021's KernelSize)"),
        gp::choice("masking", &P::v_cavity_masking, {{"smith", false}, {"v_cavity", true}},
                   "masking-shadowing: the height-correlated Smith G2 of the target NDF, as "
                   "the ground truth's facets, or 004's V-cavity G2 (Eq. 14-16)"),
    };
    d.reads_slope_correlation = [](const GlintDesc& g) {
        return std::get<P>(g.params).slope_correlation;
    };
    GlintExtraKey colours;
    colours.key = "colours";
    colours.doc =
        "1 to 8 RGB tints [[r, g, b], ...] in [0, 1], one drawn per cell (004 §7.1 colour "
        "table); absent = white";
    colours.max_colours = static_cast<int>(P{}.colour_table.size());
    colours.colour_count = [](GlintModelParams& v) -> int& { return std::get<P>(v).colour_count; };
    colours.colours = [](GlintModelParams& v) { return std::get<P>(v).colour_table.data(); };
    d.extra_keys = {colours};
    d.check = check_chermain2020;
    d.fit_material = fit_chermain2020;
    d.facet_cone = chermain2020_facet_cone;
    d.validation = {"chermain2020"};  // run by the research library (validation_suites.h)
    return d;
}

}  // namespace glintlab
