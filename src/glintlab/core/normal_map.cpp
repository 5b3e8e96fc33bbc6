#include "glintlab/core/normal_map.h"

#include <algorithm>
#include <cmath>

#include "glintlab/core/glsl.h"

GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/core/footprint_cell.glsl"
#include "glintlab/core/slope_frame.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

// The level of detail the moments are read at, relative to OpenGL's. A
// trilinear lookup at λ = log2(footprint width in texels) averages over the
// level's texel (a box of the footprint's width, variance w²/12) convolved
// with the bilinear tent (variance w²/6): a window of 3× the footprint's
// spatial variance. Means hardly notice; a covariance does: across a
// smooth slope field it grows with the window's variance, so it came out
// ~3× the footprint's and over-widened every lobe (+37 % in the far rows of
// normal_bumps_forest). log2(1/√3) makes the window's variance the
// footprint's along its minor axis; along the major axis the anisotropic
// probes' spread already is.
constexpr float kMomentLodBias = -0.79248125f;

}  // namespace

Footprint NormalMap::sample_footprint(const Footprint& footprint, float u) const {
    if (filtering != Filtering::LeanMixture || mixture <= 1) return footprint;
    const int cells = mixture * mixture;
    return shader::footprint_cell(footprint, std::clamp(int(u * float(cells)), 0, cells - 1),
                                  mixture);
}

float NormalMap::chain_weight(const Footprint& fp) const {
    return shader::lean_chain_weight(
        slopes->texture->filter_lod(slopes->transform.apply_vector(fp.duvdx),
                                    slopes->transform.apply_vector(fp.duvdy), kMomentLodBias));
}

SlopeStatistics NormalMap::lookup(glm::vec2 uv, const Footprint* footprint, bool correlated) const {
    const Footprint* fp = filtering != Filtering::None ? footprint : nullptr;
    SlopeStatistics s;
    if (!fp) {  // one point of the bilinear surface: no spread to keep
        s.mean = slope_at(uv);
        return s;
    }
    // The chain where it counts (t > 0), the surface where it does (t < 1).
    const float t = chain_weight(*fp);
    if (t > 0.0f) {
        const glm::vec4 first = slopes->lookup4(uv, fp, kMomentLodBias);
        const float second_xy = correlated ? cross_moment->lookup4(uv, fp, kMomentLodBias).x : 0.0f;
        s.mean = glm::vec2(first.x, first.y);
        s.covariance =
            shader::slope_covariance(s.mean, glm::vec2(first.z, first.w), second_xy, correlated);
    }
    if (t < 1.0f)
        shader::lean_blend_surface(t, slope_at(uv), slope_at(uv + 0.5f * fp->duvdx),
                                   slope_at(uv - 0.5f * fp->duvdx), slope_at(uv + 0.5f * fp->duvdy),
                                   slope_at(uv - 0.5f * fp->duvdy), correlated, s.mean,
                                   s.covariance);
    return s;
}

glm::vec2 NormalMap::slope_at(glm::vec2 uv) const {
    const glm::vec3 v = slopes->at(uv);
    return glm::vec2(v.x, v.y);
}

void tangent_frame_around(glm::vec3 n, glm::vec3* t, glm::vec3* b) {
    // n.z > 0 for every normal-map normal (texels below the tangent plane
    // are clamped at read time), so (1, 0, 0) − n n.x never vanishes.
    const glm::vec3 x = glm::vec3(1.0f, 0.0f, 0.0f) - n * n.x;
    *t = glm::normalize(x);
    *b = glm::cross(n, *t);
}

}  // namespace glintlab
