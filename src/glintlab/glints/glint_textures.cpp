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
    // Density and roughness usually share one packed texture (the scene
    // loader's pack_scalar_inputs): one footprint lookup gives all three.
    // An isotropic roughness map is one input on both axes.
    const TextureInput* scalars[3] = {t.density.get(), t.alpha_x_sq.get(), t.alpha_y_sq.get()};
    float values[3] = {0.0f, 0.0f, 0.0f};
    lookup_scalars(scalars, uv, footprint, values);
    // The map's values are e^{ln N} with ln N in [-20, 60]: n > 0.
    if (t.density) d.log_density = std::log(std::max(values[0], 1e-30f));
    if (t.alpha_x_sq) d.alpha_x = alpha_from_squared(values[1]);
    if (t.alpha_y_sq) d.alpha_y = alpha_from_squared(values[2]);
    if (t.alpha_x_sq || t.alpha_y_sq) d.alpha_varies = true;
    if (t.color) d.color = t.color->lookup(uv, footprint);
    if (t.base_albedo) d.base_albedo = t.base_albedo->lookup(uv, footprint);
    return d;
}

}  // namespace glintlab
