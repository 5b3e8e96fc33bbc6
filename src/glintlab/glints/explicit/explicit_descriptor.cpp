// explicit's descriptor (glint_model_descriptor.h): the ground truth; it
// enumerates the footprint's mirror facets and shades every light itself
// (explicit_model.h); D_P for GlintBxdf from its gamma-cone count.
#include <algorithm>

#include <fmt/format.h>

#include <string>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/glints/explicit/explicit_model.h"
#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {
namespace {

// N = e^log_density facets per unit uv area are enumerated one by one.
void check_explicit(JsonObject& block, GlintDesc& desc) {
    if (!(desc.log_density >= 0.0f && desc.log_density <= 30.0f)) {
        block.parent_error("log_density",
                           fmt::format("{} is out of range for the explicit model: [0, 30] (N = "
                                       "e^log_density facets per unit uv area are enumerated one "
                                       "by one)",
                                       desc.log_density));
    }
}

// What check_explicit accepts: ln density in [0, 30].
void fit_explicit(GlintDesc& desc) {
    desc.log_density = std::clamp(desc.log_density, 0.0f, 30.0f);
}

}  // namespace

GlintModelDescriptor explicit_descriptor() {
    namespace gp = glint_param;
    using P = ExplicitParams;
    GlintModelDescriptor d = make_glint_model_descriptor<P>(
        GlintModelId::Explicit, "explicit",
        "ground truth: explicitly enumerated mirror microfacets (002 Sec. 3.1, 003 Sec. 3.2)",
        {GlintLightType::Point, GlintLightType::Directional, GlintLightType::Sphere,
         GlintLightType::Environment});
    d.citations = {
        {"002", "Jakob, Hašan, Yan, Lawrence, Ramamoorthi, Marschner", 2014,
         "ACM Transactions on Graphics 33(4) (SIGGRAPH 2014)",
         "Discrete Stochastic Microfacet Models"},
        {"003", "Kneiphof, Klein", 2025, "Computer Graphics Forum 44(4) (EGSR 2025)",
         "Real-Time Image-Based Lighting of Glints"},
    };
    d.params = {
        // 002 §3.1: "a constant γ between 0.5 and 6 degrees in our scenes".
        gp::number("gamma_deg", &P::gamma_deg, 0.5, 6.0, "deg",
                   "half-angle of the query cone delta lights are spread over (002 §3.1)"),
        gp::number("max_facets_per_footprint", &P::max_facets_per_footprint, 1.0, 1e9, "",
                   "expected facets per pixel footprint above which shading fails with an "
                   "error instead of enumerating for minutes",
                   GlintParamUi::Log),
        gp::choice("over_budget", &P::subsample_over_budget,
                   {{"error", false}, {"subsample", true}},
                   "a footprint above max_facets_per_footprint: fail naming it, or enumerate one "
                   "of K x K equal parts (unbiased; for grazing and silhouette footprints)"),
    };
    d.filters_curvature = false;  // composes each facet with the curved surface instead
    d.check = check_explicit;
    d.fit_material = fit_explicit;
    d.shades_light = GLINTLAB_SHADES_LIGHT_HOOK(explicit_shades_light);
    d.light_radiance = GLINTLAB_LIGHT_RADIANCE_HOOK(explicit_light_radiance);
    d.validation = {"explicit"};  // run by the research library (validation_suites.h)
    return d;
}

}  // namespace glintlab
