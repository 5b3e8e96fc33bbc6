#include "glintlab/render/sampling_advice.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include <fmt/format.h>

namespace glintlab {

std::vector<std::string> sampling_advice(const Scene& scene) {
    std::vector<std::string> advice;
    bool environment = false;
    for (const Light& light : scene.lights)
        environment = environment || std::holds_alternative<EnvironmentLight>(light);
    const int spp = scene.render.spp;
    if (!environment || spp >= kJakob2014EnvironmentMinSpp) return advice;
    for (const MaterialDesc& m : scene.materials) {
        if (m.type != MaterialDesc::Type::Glint || m.glint.model_id != GlintModelId::Jakob2014)
            continue;
        const double error = kJakob2014EnvironmentErrorAt1Spp / std::sqrt(static_cast<double>(spp));
        const double spp_for_10 = std::pow(kJakob2014EnvironmentErrorAt1Spp / 0.1, 2.0);
        advice.push_back(fmt::format(
            "material \"{}\" (jakob2014) under an environment light: at {} spp expect a per-pixel "
            "error of about {:.0f} % (many pixels black between sparkles); {:.0f} spp give 10 % "
            "(docs/MODELS.md, jakob2014 \"Samples under environment lights\")",
            m.name, spp, 100.0 * std::min(error, 9.99), spp_for_10));
    }
    return advice;
}

}  // namespace glintlab
