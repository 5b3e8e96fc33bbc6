// zirr2016's descriptor (glint_model_descriptor.h): point and directional
// lights only (000 §3: counts for one half vector).
#include "glintlab/glints/facet_extent.h"
#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {
namespace {

// compare (facet_extent.h): R of 000 Eq. 4 with explicit's success
// probability, R = D(n) omega_h(gamma).
std::string match_zirr2016_facet_cone(GlintDesc& desc, double gamma_rad) {
    return set_facet_extent_param(desc, "microfacet_roughness",
                                  microfacet_roughness_for_cone(desc, gamma_rad));
}

}  // namespace

const GpuModelHooks& zirr2016_gpu_hooks();  // zirr2016/zirr2016_gpu*.cpp

GlintModelDescriptor zirr2016_descriptor() {
    namespace gp = glint_param;
    using P = Zirr2016Params;
    GlintModelDescriptor d = make_glint_model_descriptor<P>(
        GlintModelId::Zirr2016, "zirr2016",
        "MIP-grid binomial counting with output blending (Zirr & Kaplanyan 2016)",
        {GlintLightType::Point, GlintLightType::Directional});
    d.citations = {{"", "Zirr, Kaplanyan", 2016, "I3D 2016",
                    "Real-time Rendering of Procedural Multiscale Materials"}};
    d.set_gpu_hooks(GLINTLAB_GPU_HOOKS(zirr2016_gpu_hooks));
    d.set_export("glintlab/glints/zirr2016/zirr2016_gpu.glsl");
    d.params = {
        gp::microfacet_roughness(
            &P::microfacet_roughness,
            "R of 000 Eq. 4: p = R D(h)/D(n), the angular cell width (micro-roughness)"),
        // 1 = isotropic filtering only; 64 bounds the march (cost grows linearly).
        gp::number("max_anisotropy", &P::max_anisotropy, 1.0, 64.0, "",
                   "largest footprint ratio marched; beyond it the footprint is widened"),
        // Below 0.5 texels are under half a pixel and alias; above 8 glints
        // are blocks of 8 pixels.
        gp::number("screen_space_scale", &P::screen_space_scale, 0.5, 8.0, "",
                   "texel width in footprint minor widths: LOD = log2(minor * S)"),
    };
    d.match_facet_cone = match_zirr2016_facet_cone;
    // D sheared by the footprint's slope correlation (ndf.glsl
    // D_Microfacet_correlated): the widened lobe keeps Σ's direction.
    d.reads_slope_correlation = [](const GlintDesc&) { return true; };
    d.validation = {"zirr2016"};  // run by the research library (validation_suites.h)
    return d;
}

}  // namespace glintlab
