// `glintlab export` of chermain2020 (its descriptor's GlintModelExport): the
// dictionary of 1D marginal distributions (004 §4.4-4.5).
#include "glintlab/export/model_export.h"
#include "glintlab/glints/chermain2020/chermain2020_params.h"
#include "glintlab/glints/chermain2020/dictionary.h"

namespace glintlab {

void chermain2020_export_material(GlintExportContext& ctx) {
    const auto& p = std::get<Chermain2020Params>(ctx.material.params);
    ctx.derived_uniforms = {{{"uniform", "u_chermain2020_correlated"},
                             {"value", p.slope_correlation},
                             {"from", "slope_correlation == \"chermain2021\""}}};
    if (!ctx.resources) return;
    const Dictionary& dict = default_dictionary();
    ctx.resource("dictionary", chermain2020_dictionary_pairs(dict),
                 {{"uniform", "chermain2020_dictionary"},
                  {"format", "RG32F"},
                  {"width", dict.params.table_size},
                  {"height", dict.params.n_dists * dict.params.n_levels},
                  {"filter", "nearest"},
                  {"wrap", "clamp_to_edge"},
                  {"mipmaps", false},
                  {"meaning",
                   "004 4.4-4.5 dictionary of 1D marginal distributions: row dist * n_levels + "
                   "level; texel k holds table samples k and k + 1 (0 past the row's end), "
                   "the two values of one linear interpolation (texelFetch)"},
                  {"uniforms",
                   {{"u_chermain2020_dict_shape",
                     {dict.params.n_levels, dict.params.n_dists, dict.params.table_size}},
                    {"u_chermain2020_dict_range", {dict.params.alpha_dict, dict.slope_max}}}}});
}

}  // namespace glintlab
