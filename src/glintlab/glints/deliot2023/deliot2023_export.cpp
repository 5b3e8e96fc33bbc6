// `glintlab export` of deliot2023 (its descriptor's GlintModelExport): the
// noise table of the noise_texture variant.
#include "glintlab/glints/deliot2023/deliot2023.h"
#include "glintlab/glints/model_export.h"

namespace glintlab {

void deliot2023_export_material(GlintExportContext& ctx) {
    const auto& p = std::get<Deliot2023Params>(ctx.material.params);
    ctx.derived_uniforms = {{{"uniform", "u_deliot2023_conditional"},
                             {"value", p.conditional_gaussian},
                             {"from", "gaussian == \"conditional\""}}};
    if (!ctx.resources) return;
    std::vector<float> pairs;
    for (const glm::vec2& v : deliot2023_noise_table()) {
        pairs.push_back(v.x);
        pairs.push_back(v.y);
    }
    ctx.resource("noise", pairs,
                 {{"uniform", "u_deliot2023_noise"},
                  {"binding", 5},
                  {"used_by", "noise_texture variant"},
                  {"format", "RG32F"},
                  {"width", 64},
                  {"height", 64},
                  {"filter", "nearest"},
                  {"wrap", "repeat"},
                  {"mipmaps", false},
                  {"meaning",
                   "the two uniforms of each gated-Gaussian evaluation (000 6.3), indexed by "
                   "cell hash % 4096 (texelFetch)"}});
}

}  // namespace glintlab
