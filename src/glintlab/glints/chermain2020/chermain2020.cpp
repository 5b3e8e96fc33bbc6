#include "glintlab/glints/chermain2020/chermain2020.h"

#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/glsl.h"
#include "glintlab/glints/chermain2020/dictionary.h"
#include "glintlab/glints/glint_desc.h"

// The only translation unit that compiles chermain2020.glsl as C++. Its
// dictionary fetch reads the in-memory default dictionary (ARCHITECTURE.md
// §2: resources through fetch functions each back end defines).
GLINTLAB_SHADER_FUNCTIONS_BEGIN
float chermain2020_dict_fetch(int row, int bin) {
    const Dictionary& d = default_dictionary();
    return d.values[static_cast<size_t>(row) * d.params.table_size + bin];
}
// Geometric glint anti-aliasing's texel: the sample, the row's next one
// and the running integral (chermain2020_dictionary_filter_texels' layout).
vec3 chermain2020_dict_fetch_filter(int row, int bin) {
    const Dictionary& d = default_dictionary();
    const size_t i = static_cast<size_t>(row) * d.params.table_size + bin;
    const float next = bin + 1 < d.params.table_size ? d.values[i + 1] : 0.0f;
    return vec3(d.values[i], next, d.running_integrals[i]);
}
#include "glintlab/core/half_slope_differentials.glsl"
#include "glintlab/glints/chermain2020/chermain2020.glsl"
#include "glintlab/microfacet/ndf.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

shader::Chermain2020Dict dict_shape() {
    const Dictionary& d = default_dictionary();
    shader::Chermain2020Dict s;
    s.n_levels = d.params.n_levels;
    s.n_dists = d.params.n_dists;
    s.table_size = d.params.table_size;
    s.alpha_dict = d.params.alpha_dict;
    s.slope_max = d.slope_max;
    return s;
}

const shader::Chermain2020Dict& shape() {
    static const shader::Chermain2020Dict s = dict_shape();
    return s;
}

shader::Chermain2020Cell to_shader(const Chermain2020CellInfo& c) {
    shader::Chermain2020Cell s;
    s.kept = c.active;
    s.dist_level = c.dist_level;
    s.dist_x = c.dist_x;
    s.dist_y = c.dist_y;
    s.theta = c.theta;
    s.colour_u = 0.0f;
    return s;
}

shader::Chermain2020Colours to_shader(const Chermain2020Params& p) {
    shader::Chermain2020Colours c;
    c.count = p.colour_count;
    for (int i = 0; i < CHERMAIN2020_MAX_COLOURS; ++i)
        c.table[i] = p.colour_table[static_cast<size_t>(i)];
    return c;
}

static_assert(CHERMAIN2020_MAX_COLOURS ==
              std::tuple_size_v<decltype(Chermain2020Params::colour_table)>);

shader::Chermain2020Filter filter_of(const Chermain2020Target& t) {
    shader::Chermain2020Filter f;
    f.slope_dx = glm::vec2(t.slope_differentials.x, t.slope_differentials.y);
    f.slope_dy = glm::vec2(t.slope_differentials.z, t.slope_differentials.w);
    f.kernel = t.kernel;
    return f;
}

Chermain2020Target target_of(const GlintDesc& desc, glm::vec3 h, const ViewDifferentials* view) {
    Chermain2020Target t;
    t.alpha_x = desc.alpha_x;
    t.alpha_y = desc.alpha_y;
    t.rho = desc.slope_correlation;
    t.log_density = desc.log_density;
    t.seed = desc.seed;
    const auto& p = std::get<Chermain2020Params>(desc.params);
    if (view && p.antialiasing) {
        t.slope_differentials = shader::half_slope_differentials(h, *view);
        t.kernel = p.antialiasing_kernel;
    }
    return t;
}

}  // namespace

glm::vec3 chermain2020_ndf_rgb(glm::vec3 h, const Footprint& footprint,
                               const Chermain2020Target& target, const Chermain2020Params& params) {
    return shader::chermain2020_ndf_rgb(
        h, footprint, shape(), target.alpha_x, target.alpha_y, target.rho, target.log_density,
        target.seed, params.relative_area, params.max_anisotropy, params.density_randomization,
        to_shader(params), filter_of(target));
}

float chermain2020_ndf(glm::vec3 h, const Footprint& footprint, const Chermain2020Target& target,
                       const Chermain2020Params& params) {
    return shader::chermain2020_ndf(h, footprint, shape(), target.alpha_x, target.alpha_y,
                                    target.rho, target.log_density, target.seed,
                                    params.relative_area, params.max_anisotropy,
                                    params.density_randomization, filter_of(target));
}

glm::vec3 chermain2020_level_sdf(glm::vec2 slope, glm::vec2 uv, glm::vec3 ellipse, int level,
                                 const Chermain2020Target& target,
                                 const Chermain2020Params& params) {
    return shader::chermain2020_level_p22(slope, uv, ellipse, level, shape(), target.alpha_x,
                                          target.alpha_y, target.rho, target.log_density,
                                          params.relative_area, params.density_randomization,
                                          target.seed, to_shader(params), filter_of(target));
}

float chermain2020_marginal_box(int dist, int level, float x, float width) {
    return shader::chermain2020_marginal_box(shape(), dist, level, x, width);
}

float chermain2020_target_ndf(glm::vec3 h, const Chermain2020Target& target) {
    if (target.rho == 0.0f) return shader::D_Beckmann(h, target.alpha_x, target.alpha_y);
    if (h.z <= 0.0f) return 0.0f;
    const float c2 = h.z * h.z;
    return shader::chermain2020_target_p22(glm::vec2(-h.x / h.z, -h.y / h.z), target.alpha_x,
                                           target.alpha_y, target.rho) /
           (c2 * c2);
}

Chermain2020CellInfo chermain2020_cell(glm::ivec2 cell, int level, const Chermain2020Target& target,
                                       const Chermain2020Params& params) {
    const shader::Chermain2020Cell s =
        shader::chermain2020_cell(cell, level, shape(), target.log_density, params.relative_area,
                                  params.density_randomization, target.seed);
    return {s.kept, s.dist_level, s.dist_x, s.dist_y, s.theta};
}

float chermain2020_cell_p22(const Chermain2020CellInfo& cell, glm::vec2 slope,
                            const Chermain2020Target& target) {
    return shader::chermain2020_cell_p22(to_shader(cell), slope, shape(), target.alpha_x,
                                         target.alpha_y, target.rho);
}

glm::vec2 chermain2020_dict_slope(const Chermain2020CellInfo& cell, glm::vec2 slope,
                                  const Chermain2020Target& target) {
    return shader::chermain2020_dict_slope(to_shader(cell), slope, shape(), target.alpha_x,
                                           target.alpha_y, target.rho);
}

float chermain2020_footprint_ndf(glm::vec3 h, const Footprint& footprint, const GlintDesc& desc,
                                 const ViewDifferentials* view) {
    return chermain2020_ndf(h, footprint, target_of(desc, h, view),
                            std::get<Chermain2020Params>(desc.params));
}

glm::vec3 chermain2020_footprint_ndf_rgb(glm::vec3 h, const Footprint& footprint,
                                         const GlintDesc& desc, const ViewDifferentials* view) {
    return chermain2020_ndf_rgb(h, footprint, target_of(desc, h, view),
                                std::get<Chermain2020Params>(desc.params));
}

}  // namespace glintlab
