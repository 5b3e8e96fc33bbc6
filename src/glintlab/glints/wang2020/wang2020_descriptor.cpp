// wang2020's descriptor (glint_model_descriptor.h): environment (Eqs. 16-20),
// point and directional lights (Eq. 21) by its own three-scale evaluation;
// no sphere lights (001 has none).
#include <algorithm>

#include "glintlab/core/json_reader.h"
#include "glintlab/glints/glint_model_descriptor.h"
#include "glintlab/glints/wang2020/wang2020_model.h"

namespace glintlab {
namespace {

// 001 §4.4: DPF tables for isotropic Beckmann alpha 0.02..1; the quadtree
// stores 28-bit counts.
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
}

// What check_wang2020 requires: isotropic Beckmann, alpha in [0.02, 1] (the
// DPF roughness set, 001 §4.4), ln N <= 19.4.
void fit_wang2020(GlintDesc& desc) {
    desc.ndf = NdfType::Beckmann;
    desc.alpha_x = desc.alpha_y = std::clamp(desc.alpha_x, 0.02f, 1.0f);
    desc.log_density = std::clamp(desc.log_density, 0.0f, 19.4f);
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
    };
    d.check = check_wang2020;
    d.fit_material = fit_wang2020;
    d.shades_light = GLINTLAB_SHADES_LIGHT_HOOK(wang2020_shades_light);
    d.light_radiance = GLINTLAB_LIGHT_RADIANCE_HOOK(wang2020_light_radiance);
    d.validation = {"wang2020"};  // run by the research library (validation_suites.h)
    return d;
}

}  // namespace glintlab
