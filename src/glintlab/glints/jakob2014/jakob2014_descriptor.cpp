// jakob2014's descriptor (glint_model_descriptor.h): every light (002 §3.1,
// §4): a BRDF over the gamma cone; extended lights and environments through
// light sampling + MIS with its importance sampling.
#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/glints/facet_extent.h"
#include "glintlab/glints/glint_model_descriptor.h"
#include "glintlab/glints/jakob2014/jakob2014.h"

namespace glintlab {
namespace {

// N = e^log_density particles per unit uv area must be an exact integer in
// double precision.
void check_jakob2014(JsonObject& block, GlintDesc& desc) {
    if (double(desc.log_density) > jakob2014::kMaxLogDensity) {
        block.parent_error(
            "log_density",
            fmt::format("{} is out of range for the jakob2014 model: at most {} (N = e^log_density "
                        "particles per unit uv area must be an exact integer in double precision, "
                        "N <= 2^53)",
                        desc.log_density, jakob2014::kMaxLogDensity));
    }
}

// What check_jakob2014 accepts: N = e^log_density <= 2^53; the largest float
// not above the (double) bound, since float(36.7) rounds above it.
void fit_jakob2014(GlintDesc& desc) {
    float max = static_cast<float>(jakob2014::kMaxLogDensity);
    if (static_cast<double>(max) > jakob2014::kMaxLogDensity) max = std::nextafter(max, 0.0f);
    desc.log_density = std::min(desc.log_density, max);
}

// compare (facet_extent.h): the search cone gamma is explicit's own
// definition (the reflected direction within gamma of the light).
std::string match_jakob2014_facet_cone(GlintDesc& desc, double gamma_rad) {
    return set_facet_cone_param(desc, "gamma_deg", gamma_rad);
}

}  // namespace

GlintModelDescriptor jakob2014_descriptor() {
    namespace gp = glint_param;
    using P = Jakob2014Params;
    GlintModelDescriptor d = make_glint_model_descriptor<P>(
        GlintModelId::Jakob2014, "jakob2014",
        "discrete stochastic microfacets, 4-D hierarchy counting (Jakob et al. 2014)",
        {GlintLightType::Point, GlintLightType::Directional, GlintLightType::Sphere,
         GlintLightType::Environment});
    d.citations = {{"002", "Jakob, Hašan, Yan, Lawrence, Ramamoorthi, Marschner", 2014,
                    "ACM Transactions on Graphics 33(4) (SIGGRAPH 2014)",
                    "Discrete Stochastic Microfacet Models"}};
    d.params = {
        // 002 §3.1: "a constant γ between 0.5 and 6 degrees in our scenes".
        gp::number("gamma_deg", &P::gamma_deg, 0.5, 6.0, "deg",
                   "query cone radius gamma around the outgoing direction (002 §3.1)"),
        gp::boolean("chromatic", &P::chromatic,
                    "per-particle Dirichlet areas per colour channel (002 §3.5, Fig. 8)"),
        // ε: 0 = exact traversal (never approximate); the paper tried 1 % and uses 10 %.
        gp::number("error_threshold", &P::error_threshold, 0.0, 0.5, "",
                   "epsilon of the adaptive error criterion (002 Eq. 10); 0 = exact traversal"),
        // Below 8 levels a 1e6-particle query cannot resolve single particles;
        // above 28 the node ids (4^depth) would not fit 64 bits.
        gp::integer("max_depth", &P::max_depth, 8, 28, "",
                    "deepest node of the 4-D hierarchy (authors' maxDepth 20)"),
        gp::number("query_area", &P::query_area, 1e-16, 1.0, "uv area",
                   "E[A(query)] of 002 Eq. 11: the expected uv area of one query",
                   GlintParamUi::Log),
    };
    // A per-hit α would build one NDF integral table per pixel (snapped_alpha).
    d.filters_curvature = false;
    d.check = check_jakob2014;
    d.fit_material = fit_jakob2014;
    d.match_facet_cone = match_jakob2014_facet_cone;
    // Its particles' NDF sheared by a normal map's slope correlation (one
    // integral table per snapped (α_x, α_y, ρ): jakob2014.cpp snapped_rho).
    d.reads_slope_correlation = [](const GlintDesc&) { return true; };
    d.validation = {"jakob2014"};  // run by the research library (validation_suites.h)
    return d;
}

}  // namespace glintlab
