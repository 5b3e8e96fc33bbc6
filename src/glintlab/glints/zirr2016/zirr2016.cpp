#include "glintlab/glints/zirr2016/zirr2016.h"

#include <variant>

#include "glintlab/core/glsl.h"
#include "glintlab/glints/glint_desc.h"

// The only translation unit that compiles zirr2016.glsl as C++.
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/zirr2016/zirr2016.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {

float zirr2016_ndf(glm::vec3 h, const Footprint& footprint, const Zirr2016Target& target,
                   const Zirr2016Params& params) {
    return shader::zirr2016_ndf(
        h, footprint, target.ndf, target.alpha_x, target.alpha_y, target.rho, target.log_density,
        target.seed, params.microfacet_roughness, params.max_anisotropy, params.screen_space_scale);
}

float zirr2016_target_ndf(glm::vec3 h, const Zirr2016Target& target) {
    return shader::D_Microfacet_correlated(target.ndf, h, target.alpha_x, target.alpha_y,
                                           target.rho);
}

float zirr2016_footprint_ndf(glm::vec3 h, const Footprint& footprint, const GlintDesc& desc) {
    Zirr2016Target t;
    t.ndf = desc.ndf == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN;
    t.alpha_x = desc.alpha_x;
    t.alpha_y = desc.alpha_y;
    t.rho = desc.slope_correlation;
    t.log_density = desc.log_density;
    t.seed = desc.seed;
    return zirr2016_ndf(h, footprint, t, std::get<Zirr2016Params>(desc.params));
}

}  // namespace glintlab
