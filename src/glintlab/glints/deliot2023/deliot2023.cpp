#include "glintlab/glints/deliot2023/deliot2023.h"

#include <variant>

#include "glintlab/core/glsl.h"
#include "glintlab/glints/glint_desc.h"

// The only translation unit that compiles deliot2023.glsl (and the shared
// files it includes) as C++.
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/deliot2023/deliot2023.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {

float deliot2023_ndf(glm::vec3 h, const Footprint& footprint, const Deliot2023Target& target,
                     const Deliot2023Params& params) {
    return shader::deliot2023_ndf(
        h, footprint, target.ndf, target.alpha_x, target.alpha_y, target.rho, target.log_density,
        target.seed, params.microfacet_roughness, params.screen_space_scale,
        params.density_randomization, params.original_defects, params.conditional_gaussian);
}

float deliot2023_target_ndf(glm::vec3 h, const Deliot2023Target& target) {
    return shader::D_Microfacet_correlated(target.ndf, h, target.alpha_x, target.alpha_y,
                                           target.rho);
}

glm::vec3 deliot2023_footprint_ellipse(glm::vec2 duvdx, glm::vec2 duvdy, bool original_defects) {
    return shader::deliot2023_footprint_ellipse(duvdx, duvdy, original_defects);
}

float deliot2023_footprint_ndf(glm::vec3 h, const Footprint& footprint, const GlintDesc& desc) {
    Deliot2023Target t;
    t.ndf = desc.ndf == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN;
    t.alpha_x = desc.alpha_x;
    t.alpha_y = desc.alpha_y;
    t.rho = desc.slope_correlation;
    t.log_density = desc.log_density;
    t.seed = desc.seed;
    return deliot2023_ndf(h, footprint, t, std::get<Deliot2023Params>(desc.params));
}

}  // namespace glintlab
