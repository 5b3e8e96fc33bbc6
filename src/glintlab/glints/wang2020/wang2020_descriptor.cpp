// wang2020's descriptor (glint_model_descriptor.h): environment (Eqs. 16-20),
// point and directional lights (Eq. 21) by its own three-scale evaluation;
// no sphere lights (001 has none).
#include <algorithm>
#include <cstdint>
#include <string>
#include <variant>

#include <fmt/format.h>

#include "glintlab/core/json_reader.h"
#include "glintlab/glints/facet_extent.h"
#include "glintlab/glints/glint_model_descriptor.h"
#include "glintlab/glints/wang2020/wang2020_model.h"
#include "glintlab/glints/wang2020/wang2020_quadtree.h"

namespace glintlab {
namespace {

// `depth` against the material's N (wang2020_quadtree.h): at most
// kMaxParticlesPerLeaf particles per leaf (the micro and meso scales
// enumerate the particles of every leaf the footprint cuts) and at most
// kMaxQuadtreeNodes nodes. Depths 8..13 pass both at every log_density in
// [0, 19.4]; the default 11 (§6) always does.
void check_wang2020_depth(JsonObject& block, const GlintDesc& desc) {
    namespace w = wang2020;
    const int depth = std::get<Wang2020Params>(desc.params).depth;
    const uint64_t n = wang2020_particles(desc.log_density);
    const int lo = w::min_quadtree_depth(n), hi = w::max_quadtree_depth(n);
    const double per_leaf = w::particles_per_leaf(n, depth);
    const double nodes = w::quadtree_node_bound(n, depth);
    if (per_leaf <= w::kMaxParticlesPerLeaf && nodes <= w::kMaxQuadtreeNodes) return;
    // lo <= hi at every log_density check_wang2020 accepts (8..13 always pass).
    const std::string allowed = fmt::format("allowed at this density: depth {}..{}", lo, hi);
    if (per_leaf > w::kMaxParticlesPerLeaf)
        block.error("depth",
                    fmt::format("wang2020 depth {} at log_density {} leaves {:.0f} particles per "
                                "quadtree leaf (N = {} per uv tile / 4^{}), more than {:.0f} (the "
                                "micro and meso scales enumerate the particles of every leaf the "
                                "footprint cuts); use depth {} or more ({})",
                                depth, desc.log_density, per_leaf, n, depth,
                                w::kMaxParticlesPerLeaf, lo, allowed));
    block.error("depth",
                fmt::format("wang2020 depth {} at log_density {} needs up to {:.0f} quadtree nodes "
                            "({:.0f} MB) for N = {} particles per uv tile, more than {:.0f} "
                            "({:.0f} MB); use depth {} or less ({})",
                            depth, desc.log_density, nodes, nodes * 8.0 / 1e6, n,
                            w::kMaxQuadtreeNodes, w::kMaxQuadtreeNodes * 8.0 / 1e6, hi, allowed));
}

// 001 §4.4: DPF tables for isotropic Beckmann alpha 0.02..1; the quadtree
// stores 28-bit counts; `depth` within the quadtree's bounds.
void check_wang2020(JsonObject& block, GlintDesc& desc) {
    if (desc.ndf != NdfType::Beckmann || desc.alpha_x != desc.alpha_y || desc.alpha_x < 0.02f ||
        desc.alpha_x > 1.0f)
        block.error("",
                    "wang2020 needs an isotropic Beckmann material with roughness in [0.02, 1] "
                    "(\"ndf\": \"beckmann\"; 001 §4.4: DPF tables for alpha 0.02..1)");
    if (!(desc.log_density >= 0.0f && desc.log_density <= 19.4f))
        block.error("",
                    "wang2020 needs log_density in [0, 19.4] (at most 2^28 particles per uv "
                    "tile: the quadtree stores 28-bit counts)");
    check_wang2020_depth(block, desc);
}

// What check_wang2020 requires: isotropic Beckmann, alpha in [0.02, 1] (the
// DPF roughness set, 001 §4.4), ln N <= 19.4, `depth` within the quadtree's
// bounds at that N (never empty in that range: 8..13 always pass).
void fit_wang2020(GlintDesc& desc) {
    desc.ndf = NdfType::Beckmann;
    desc.alpha_x = desc.alpha_y = std::clamp(desc.alpha_x, 0.02f, 1.0f);
    desc.log_density = std::clamp(desc.log_density, 0.0f, 19.4f);
    if (auto* p = std::get_if<Wang2020Params>(&desc.params)) {
        const uint64_t n = wang2020_particles(desc.log_density);
        p->depth =
            std::clamp(p->depth, wang2020::min_quadtree_depth(n), wang2020::max_quadtree_depth(n));
    }
}

// compare (facet_extent.h): the search cone gamma is explicit's own
// definition (the reflected direction within gamma of the light).
std::string match_wang2020_facet_cone(GlintDesc& desc, double gamma_rad) {
    return set_facet_cone_param(desc, "gamma_deg", gamma_rad);
}

}  // namespace

const GpuModelHooks& wang2020_gpu_hooks();               // wang2020/wang2020_gpu*.cpp
void wang2020_export_material(GlintExportContext& ctx);  // wang2020/wang2020_export.cpp

GlintModelDescriptor wang2020_descriptor() {
    namespace gp = glint_param;
    using P = Wang2020Params;
    GlintModelDescriptor d = make_glint_model_descriptor<P>(
        GlintModelId::Wang2020, "wang2020",
        "prefiltered discrete stochastic microfacets, three-scale (Wang et al. 2020)",
        {GlintLightType::Point, GlintLightType::Directional, GlintLightType::Environment});
    d.citations = {{"001", "Wang, Deng, Holzschuch", 2020, "Computer Graphics Forum 39(6)",
                    "Real-Time Glints Rendering with Pre-Filtered Discrete Stochastic "
                    "Microfacets"}};
    d.set_gpu_hooks(GLINTLAB_GPU_HOOKS(wang2020_gpu_hooks));
    // The renderer's glue reads the tables from SSBOs (wang2020_gpu.glsl);
    // the export reads them from textures in every language (GLSL ES 3.00
    // has no storage buffers), the rest of the glue is shared
    // (wang2020_glue_common.glsl).
    d.set_export("glintlab/glints/wang2020/wang2020_export_textures.glsl",
                 GLINTLAB_EXPORT_HOOK(wang2020_export_material));
    d.params = {
        gp::number("gamma_deg", &P::gamma_deg, 1.0, 30.0, "deg",
                   "search cone half-angle gamma (001 §3.1)"),
        gp::integer("depth", &P::depth, 1, 16, "", "quadtree depth (001 §6)"),
        gp::integer("dpf_theta", &P::dpf_theta, 2, 180, "",
                    "DPF table theta_i and theta_o resolution (001 Table 2)"),
        gp::integer("dpf_phi", &P::dpf_phi, 2, 360, "",
                    "DPF table delta-phi resolution (001 Table 2)"),
        gp::integer("prefilter_samples", &P::prefilter_samples, 1, 4096, "",
                    "K of 001 Eq. 16: samples per prefiltered environment entry"),
        gp::boolean("directional_occlusion", &P::directional_occlusion,
                    "001 §4.4: one mirror-direction visibility ray"),
        gp::boolean("blur", &P::blur,
                    "001 §4.4: the two Gaussian blurs (9 and 3 taps) over the glint layer"),
        gp::choice("micro", &P::micro_per_particle,
                   {{"per_particle", true}, {"as_published", false}},
                   "micro scale: per-particle hashed normals with blended scale transitions "
                   "(default) or 001 Eq. 20's acceptance test"),
        gp::choice("prefilter", &P::prefilter_mis, {{"mis", true}, {"as_published", false}},
                   "001 Eq. 16 prefilter: BRDF + environment samples by MIS (default) or BRDF "
                   "samples only"),
        gp::choice("dpf_roughness", &P::dpf_exact_roughness,
                   {{"exact", true}, {"as_published", false}},
                   "DPF table of the material's own roughness (default) or 001 §4.4's linear "
                   "interpolation between the two bracketing tables"),
        gp::choice("scale_count", &P::scale_count_effective,
                   {{"effective", true}, {"particles", false}},
                   "what selects the scale with \"micro\": \"per_particle\": the effective "
                   "particle count n r of the micro estimate (default; r = P under lights, "
                   "E[f]^2/E[f^2] under the environment) or 001 §4.3's particle count n"),
        gp::choice("particle_radiance", &P::particle_radiance_point,
                   {{"point", true}, {"cone", false}},
                   "what a particle of \"micro\": \"per_particle\" reflects under the "
                   "environment: the value in its mirror direction (default, as an explicit "
                   "facet) or the gamma-cone average"),
        gp::choice("glint_blur", &P::glint_blur,
                   {{"auto", P::GlintBlur::Auto},
                    {"none", P::GlintBlur::None},
                    {"as_published", P::GlintBlur::AsPublished}},
                   "with \"blur\": 001 §4.4's 3-tap Gaussian blur of the glint layer where the "
                   "image has one sample per pixel (GPU, CPU at 1 spp) and none where the CPU "
                   "supersamples (default), never, or always as published"),
    };
    d.textured_density = d.textured_roughness = d.filters_curvature = false;
    d.untextured_reason =
        "its quadtree tables (001 §5) are built for one roughness and one facet count per material";
    d.check = check_wang2020;
    d.fit_material = fit_wang2020;
    d.shades_light = GLINTLAB_SHADES_LIGHT_HOOK(wang2020_shades_light);
    d.light_radiance = GLINTLAB_LIGHT_RADIANCE_HOOK(wang2020_light_radiance);
    d.match_facet_cone = match_wang2020_facet_cone;
    d.validation = {"wang2020"};  // run by the research library (validation_suites.h)
    return d;
}

}  // namespace glintlab
