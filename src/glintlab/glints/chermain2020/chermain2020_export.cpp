// `glintlab export` of chermain2020 (its descriptor's GlintModelExport): the
// dictionary of 1D marginal distributions (004 §4.4-4.5).
#include "glintlab/glints/chermain2020/chermain2020_params.h"
#include "glintlab/glints/chermain2020/dictionary.h"
#include "glintlab/glints/model_export.h"

namespace glintlab {

void chermain2020_export_material(GlintExportContext& ctx) {
    const auto& p = std::get<Chermain2020Params>(ctx.material.params);
    ctx.derived_uniforms = {
        {{"uniform", "u_chermain2020_correlated"},
         {"value", p.slope_correlation},
         {"from", "slope_correlation == \"chermain2021\""}},
        {{"uniform", "u_chermain2020_ggaa_kernel"},
         {"value", p.antialiasing ? p.antialiasing_kernel : 0.0f},
         {"from", "antialiasing == \"chermain2021\" ? antialiasing_kernel : 0 (0: unfiltered)"}}};
    if (!ctx.resources) return;
    const Dictionary& dict = default_dictionary();
    // One table for both reads (GLINTLAB_CHERMAIN2020_ONE_TABLE): the pairs
    // and, for Chermain et al. 2021's geometric glint anti-aliasing, each
    // row's running integral, so a host switches the filter by
    // u_chermain2020_ggaa_kernel alone (2.25 MiB instead of the pairs' 1.5).
    ctx.resource("dictionary", chermain2020_dictionary_filter_texels(dict),
                 {{"uniform", "chermain2020_dictionary"},
                  {"format", "RGB32F"},
                  {"width", dict.params.table_size},
                  {"height", dict.params.n_dists * dict.params.n_levels},
                  {"filter", "nearest"},
                  {"wrap", "clamp_to_edge"},
                  {"mipmaps", false},
                  {"meaning",
                   "004 4.4-4.5 dictionary of 1D marginal distributions: row dist * n_levels + "
                   "level; texel k holds table samples k and k + 1 (0 past the row's end), "
                   "the two values of one linear interpolation, and the row's integral from 0 "
                   "to sample k (Chermain et al. 2021's box filter, read where "
                   "u_chermain2020_ggaa_kernel > 0); texelFetch"},
                  {"uniforms",
                   {{"u_chermain2020_dict_shape",
                     {dict.params.n_levels, dict.params.n_dists, dict.params.table_size}},
                    {"u_chermain2020_dict_range", {dict.params.alpha_dict, dict.slope_max}}}}});
}

}  // namespace glintlab
