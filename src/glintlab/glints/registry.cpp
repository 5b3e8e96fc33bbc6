#include "glintlab/glints/registry.h"

#include "glintlab/glints/chermain2020/chermain2020.h"
#include "glintlab/glints/deliot2023/deliot2023.h"
#include "glintlab/glints/explicit/explicit_model.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025.h"
#include "glintlab/glints/jakob2014/jakob2014.h"
#include "glintlab/glints/wang2020/wang2020_model.h"
#include "glintlab/glints/zirr2016/zirr2016.h"
#include "glintlab/scene/json_reader.h"
#include "glintlab/scene/scene.h"

namespace glintlab {
namespace {

// `smooth`: the Cook–Torrance limit every glint model converges to; it has
// no parameters of its own.
void read_smooth_params(JsonObject& block, GlintDesc& desc) {
    desc.params = SmoothParams{};
    block.finish();
}

const GlintModelInfo kModels[] = {
    {GlintModelId::Smooth, "smooth",
     "smooth microfacet BRDF (Cook-Torrance / Walter et al. 2007), the limit of every glint model",
     true, true, true, true, read_smooth_params},
    // Point and directional lights only (000 §8: no extended lights).
    {GlintModelId::Deliot2023, "deliot2023",
     "distributed binomial laws on anisotropic grids (Deliot & Belcour 2023)", true, true, false,
     false, read_deliot2023_params},
    // Point and directional lights only (000 §3: counts for one half vector).
    {GlintModelId::Zirr2016, "zirr2016",
     "MIP-grid binomial counting with output blending (Zirr & Kaplanyan 2016)", true, true, false,
     false, read_zirr2016_params},
    // Point and directional lights only: D_P is evaluated at one half vector.
    {GlintModelId::Chermain2020, "chermain2020",
     "multiscale SDF dictionary over a MIP hierarchy (Chermain et al. 2020)", true, true, false,
     false, read_chermain2020_params},
    // Ground truth: enumerates the footprint's mirror facets and shades every
    // light itself (explicit_model.h); D_P for GlintBxdf from its γ-cone count.
    {GlintModelId::Explicit, "explicit",
     "ground truth: explicitly enumerated mirror microfacets (002 Sec. 3.1, 003 Sec. 3.2)", true,
     true, true, true, read_explicit_params, explicit_shades_light, explicit_light_radiance},
    // Every light (002 §3.1, §4): a BRDF over the γ cone; extended lights and
    // environments through light sampling + MIS with its importance sampling.
    {GlintModelId::Jakob2014, "jakob2014",
     "discrete stochastic microfacets, 4-D hierarchy counting (Jakob et al. 2014)", true, true, true,
     true, read_jakob2014_params},
    // Environment, sphere and sun-like directional lights by its own counting
    // (003 Eq. 17; K = 1 area lights, 003 Eq. 6-9); point and delta
    // directional lights through deliot2023's D_P (003 Table 1).
    {GlintModelId::Kneiphof2025, "kneiphof2025",
     "image-based lighting of glints, multinomial over K radiance levels (Kneiphof & Klein 2025)",
     true, true, true, true, read_kneiphof2025_params, kneiphof2025_shades_light,
     kneiphof2025_light_radiance},
    // Environment (Eqs. 16-20), point and directional lights (Eq. 21) by its
    // own three-scale evaluation; no sphere lights (001 has none).
    {GlintModelId::Wang2020, "wang2020",
     "prefiltered discrete stochastic microfacets, three-scale (Wang et al. 2020)", true, true,
     false, true, read_wang2020_params, wang2020_shades_light, wang2020_light_radiance},
};

}  // namespace

std::span<const GlintModelInfo> glint_models() {
    return kModels;
}

const GlintModelInfo* find_glint_model(std::string_view name) {
    for (const GlintModelInfo& m : kModels)
        if (m.name == name) return &m;
    return nullptr;
}

const GlintModelInfo* find_glint_model(GlintModelId id) {
    for (const GlintModelInfo& m : kModels)
        if (m.id == id) return &m;
    return nullptr;
}

std::string glint_model_names() {
    std::string s;
    for (const GlintModelInfo& m : kModels) {
        if (!s.empty()) s += ", ";
        s += m.name;
    }
    return s;
}

}  // namespace glintlab
