// `smooth`: the Cook-Torrance limit every glint model converges to; it has
// no parameters of its own.
#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {

GlintModelDescriptor smooth_descriptor() {
    GlintModelDescriptor d;
    d.id = GlintModelId::Smooth;
    d.name = "smooth";
    d.description =
        "smooth microfacet BRDF (Cook-Torrance / Walter et al. 2007), the limit of every glint "
        "model";
    d.citations = {
        {"", "Walter, Marschner, Li, Torrance", 2007, "EGSR",
         "Microfacet Models for Refraction through Rough Surfaces"},
        {"", "Heitz", 2014, "JCGT 3(2)",
         "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs"},
    };
    d.lights = {GlintLightType::Point, GlintLightType::Directional, GlintLightType::Sphere,
                GlintLightType::Environment};
    d.gpu = true;
    d.default_params = [] { return GlintModelParams(SmoothParams{}); };
    return d;
}

}  // namespace glintlab
