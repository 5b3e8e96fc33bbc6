#include "glintlab/glints/glint_textures.h"

#include <algorithm>
#include <cmath>

namespace glintlab {

float alpha_from_squared(float alpha_sq) {
    return std::clamp(std::sqrt(std::max(alpha_sq, 0.0f)), 1e-3f, 1.0f);
}

GlintDesc resolve_glint_textures(const GlintDesc& desc, glm::vec2 uv, const Footprint* footprint) {
    GlintDesc d = desc;
    if (!desc.textures) return d;
    const GlintTextures& t = *desc.textures;
    if (t.density) {
        const float n = t.density->lookup(uv, footprint).x;
        // The map's values are e^{ln N} with ln N in [-20, 60]: n > 0.
        d.log_density = std::log(std::max(n, 1e-30f));
    }
    if (t.alpha_x_sq) d.alpha_x = alpha_from_squared(t.alpha_x_sq->lookup(uv, footprint).x);
    // An isotropic roughness map is one texture on both axes: one lookup.
    if (t.alpha_y_sq && t.alpha_y_sq == t.alpha_x_sq)
        d.alpha_y = d.alpha_x;
    else if (t.alpha_y_sq)
        d.alpha_y = alpha_from_squared(t.alpha_y_sq->lookup(uv, footprint).x);
    if (t.alpha_x_sq || t.alpha_y_sq) d.alpha_varies = true;
    if (t.color) d.color = t.color->lookup(uv, footprint);
    if (t.base_albedo) d.base_albedo = t.base_albedo->lookup(uv, footprint);
    return d;
}

}  // namespace glintlab
