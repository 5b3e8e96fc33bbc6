#include "glintlab/glints/zirr2016/zirr2016.h"

#include <variant>

#include "glintlab/core/glsl.h"
#include "glintlab/scene/json_reader.h"
#include "glintlab/scene/scene.h"

// The only translation unit that compiles zirr2016.glsl as C++.
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/zirr2016/zirr2016.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {

float zirr2016_ndf(glm::vec3 h, const Footprint& footprint, const Zirr2016Target& target,
                   const Zirr2016Params& params) {
    return shader::zirr2016_ndf(h, footprint, target.ndf, target.alpha_x, target.alpha_y,
                                target.log_density, target.seed, params.microfacet_roughness,
                                params.max_anisotropy, params.screen_space_scale);
}

float zirr2016_target_ndf(glm::vec3 h, const Zirr2016Target& target) {
    return shader::D_Microfacet(target.ndf, h, target.alpha_x, target.alpha_y);
}

float zirr2016_footprint_ndf(glm::vec3 h, const Footprint& footprint, const GlintDesc& desc) {
    Zirr2016Target t;
    t.ndf = desc.ndf == NdfType::GGX ? shader::NDF_GGX : shader::NDF_BECKMANN;
    t.alpha_x = desc.alpha_x;
    t.alpha_y = desc.alpha_y;
    t.log_density = desc.log_density;
    t.seed = desc.seed;
    return zirr2016_ndf(h, footprint, t, std::get<Zirr2016Params>(desc.params));
}

void read_zirr2016_params(JsonObject& block, GlintDesc& desc) {
    Zirr2016Params p;
    // R in (0, 1] (000 §3); 1e-4 stands for the open end: below it the angular
    // cells h.xy / R are finer than fp32 resolves near the normal.
    p.microfacet_roughness =
        static_cast<float>(block.number("microfacet_roughness", p.microfacet_roughness, 1e-4, 1.0));
    // 1 = isotropic filtering only; 64 bounds the march (cost grows linearly).
    p.max_anisotropy =
        static_cast<float>(block.number("max_anisotropy", p.max_anisotropy, 1.0, 64.0));
    // Below 0.5 texels are under half a pixel and alias; above 8 glints are
    // blocks of 8 pixels.
    p.screen_space_scale =
        static_cast<float>(block.number("screen_space_scale", p.screen_space_scale, 0.5, 8.0));
    desc.params = p;
    block.finish();
}

}  // namespace glintlab
