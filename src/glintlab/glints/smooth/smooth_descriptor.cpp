// `smooth`: the Cook-Torrance limit every glint model converges to; it has
// no parameters of its own.
#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {

const GpuModelHooks& smooth_gpu_hooks();  // smooth/smooth_gpu*.cpp

GlintModelDescriptor smooth_descriptor() {
    GlintModelDescriptor d = make_glint_model_descriptor<SmoothParams>(
        GlintModelId::Smooth, "smooth",
        "smooth microfacet BRDF (Cook-Torrance / Walter et al. 2007), the limit of every glint "
        "model",
        {GlintLightType::Point, GlintLightType::Directional, GlintLightType::Sphere,
         GlintLightType::Environment});
    d.citations = {
        {"", "Walter, Marschner, Li, Torrance", 2007, "EGSR",
         "Microfacet Models for Refraction through Rough Surfaces"},
        {"", "Heitz", 2014, "JCGT 3(2)",
         "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs"},
    };
    d.set_gpu_hooks(GLINTLAB_GPU_HOOKS(smooth_gpu_hooks));
    d.set_export("glintlab/glints/smooth_gpu.glsl");
    // D sheared by the footprint's slope correlation (ndf.glsl
    // D_Microfacet_correlated): the widened lobe keeps Σ's direction.
    d.reads_slope_correlation = [](const GlintDesc&) { return true; };
    return d;
}

}  // namespace glintlab
