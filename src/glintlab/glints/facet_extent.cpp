#include "glintlab/glints/facet_extent.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/glints/glint_model_descriptor.h"
#include "glintlab/glints/registry.h"

namespace glintlab {

double facet_cone_half_vector_solid_angle(double gamma_rad) {
    // 1 - cos gamma = 2 sin^2(gamma / 2), without cancellation at 1 degree.
    const double s = std::sin(0.5 * gamma_rad);
    return std::numbers::pi * s * s;
}

double microfacet_roughness_for_cone(const GlintDesc& desc, double gamma_rad) {
    const double d_n = 1.0 / (std::numbers::pi * double(desc.alpha_x) * double(desc.alpha_y));
    return d_n * facet_cone_half_vector_solid_angle(gamma_rad);
}

double cone_for_gaussian_slope_lobe(double sigma_x, double sigma_y) {
    // 1 - cos gamma = 2 sin^2(gamma / 2) = 8 sx sy.
    return 2.0 * std::asin(std::min(1.0, 2.0 * std::sqrt(sigma_x * sigma_y)));
}

std::string set_facet_extent_param(GlintDesc& desc, std::string_view key, double wanted) {
    const GlintModelDescriptor* model = find_glint_model(desc.model_id);
    for (const GlintParam& p : model->params) {
        if (p.key != key) continue;
        const double v = std::clamp(wanted, p.min, p.max);
        p.set(desc.params, GlintParamValue(v));
        if (v == wanted) return fmt::format("{} {:.4g}", key, v);
        return fmt::format("{} {:.4g} (clamped to its range {}; wanted {:.4g})", key, v,
                           p.range_text(), wanted);
    }
    fail("{}: no parameter \"{}\" (facet_extent.h)", model->name, key);
}

std::string set_facet_cone_param(GlintDesc& desc, std::string_view key, double gamma_rad) {
    return set_facet_extent_param(desc, key, gamma_rad * 180.0 / std::numbers::pi);
}

}  // namespace glintlab
