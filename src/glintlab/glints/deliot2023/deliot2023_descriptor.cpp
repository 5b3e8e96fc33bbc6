// deliot2023's descriptor (glint_model_descriptor.h): point and directional
// lights only (000 §8: the counting ignores a light's extent).
#include "glintlab/glints/facet_extent.h"
#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {
namespace {

// compare (facet_extent.h): R of 000 Eq. 4 with explicit's success
// probability, R = D(n) omega_h(gamma).
std::string match_deliot2023_facet_cone(GlintDesc& desc, double gamma_rad) {
    return set_facet_extent_param(desc, "microfacet_roughness",
                                  microfacet_roughness_for_cone(desc, gamma_rad));
}

}  // namespace

const GpuModelHooks& deliot2023_gpu_hooks();               // deliot2023/deliot2023_gpu*.cpp
void deliot2023_export_material(GlintExportContext& ctx);  // deliot2023/deliot2023_export.cpp

GlintModelDescriptor deliot2023_descriptor() {
    namespace gp = glint_param;
    using P = Deliot2023Params;
    GlintModelDescriptor d = make_glint_model_descriptor<P>(
        GlintModelId::Deliot2023, "deliot2023",
        "distributed binomial laws on anisotropic grids (Deliot & Belcour 2023)",
        {GlintLightType::Point, GlintLightType::Directional});
    d.citations = {{"000", "Deliot, Belcour", 2023, "HPG 2023 (PACMCGIT 6(3))",
                    "Real-Time Rendering of Glinty Appearances using Distributed Binomial Laws "
                    "on Anisotropic Grids"}};
    d.set_gpu_hooks(GLINTLAB_GPU_HOOKS(deliot2023_gpu_hooks));
    GlintModelExport& e = d.set_export("glintlab/glints/deliot2023/deliot2023_gpu.glsl",
                                       GLINTLAB_EXPORT_HOOK(deliot2023_export_material));
    e.variant = "noise_texture";
    e.variant_glue = "glintlab/glints/deliot2023/deliot2023_noise_texture_gpu.glsl";
    d.params = {
        gp::microfacet_roughness(
            &P::microfacet_roughness,
            "R of 000 Eq. 4: p = R D(h)/D(n), the angular cell size (micro-roughness)"),
        // Below 0.5 px glints are smaller than a pixel and alias; above 8 px the
        // cells exceed what the authors' 1.5-2 px range suggests anyone wants.
        gp::number("screen_space_scale", &P::screen_space_scale, 0.5, 8.0, "px",
                   "minimum glint size in pixels: LOD = log2(minor axis * S / 2)"),
        gp::number("density_randomization", &P::density_randomization, 0.0, 50.0, "",
                   "std-dev of the per-cell jitter of ln(density) (the authors clamp to [0, 50])"),
        gp::boolean("original_defects", &P::original_defects,
                    "reproduce the original HLSL's defects (docs/MODELS.md) for comparisons"),
        gp::choice("gaussian", &P::conditional_gaussian,
                   {{"conditional", true}, {"single_gated", false}},
                   "the count's Gaussian: conditioned on the gate with its mean kept exact "
                   "(unbiased), or 003 Eq. 23's single-gated law as published"),
    };
    d.match_facet_cone = match_deliot2023_facet_cone;
    // D sheared by the footprint's slope correlation (ndf.glsl
    // D_Microfacet_correlated): the widened lobe keeps Σ's direction.
    d.reads_slope_correlation = [](const GlintDesc&) { return true; };
    d.validation = {"deliot2023"};  // run by the research library (validation_suites.h)
    return d;
}

}  // namespace glintlab
