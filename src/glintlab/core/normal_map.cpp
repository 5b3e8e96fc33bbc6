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

SlopeStatistics NormalMap::lookup(glm::vec2 uv, const Footprint* footprint) const {
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
        s.mean = glm::vec2(first.x, first.y);
        // Σ_ii = E[s_i²] − s̄_i²; rounding can leave it slightly negative.
        s.covariance = glm::vec3(std::max(first.z - s.mean.x * s.mean.x, 0.0f),
                                 std::max(first.w - s.mean.y * s.mean.y, 0.0f), 0.0f);
    }
    if (t < 1.0f) blend_surface(uv, *fp, t, false, s.mean, s.covariance);
    return s;
}

void NormalMap::blend_surface(glm::vec2 uv, const Footprint& fp, float t, bool correlated,
                              glm::vec2& mean, glm::vec3& cov) const {
    shader::lean_blend_surface(t, slope_at(uv), slope_at(uv + 0.5f * fp.duvdx),
                               slope_at(uv - 0.5f * fp.duvdx), slope_at(uv + 0.5f * fp.duvdy),
                               slope_at(uv - 0.5f * fp.duvdy), correlated, mean, cov);
}

float NormalMap::covariance_xy(glm::vec2 uv, const Footprint* footprint,
                               const SlopeStatistics& s) const {
    const Footprint* fp = filtering != Filtering::None ? footprint : nullptr;
    if (!fp) return 0.0f;
    // The chain's Σ_xy about the chain's mean, then the same blend as lookup's.
    const float t = chain_weight(*fp);
    glm::vec2 mean(0.0f);
    glm::vec3 cov(0.0f);
    if (t > 0.0f) {
        const glm::vec4 first = slopes->lookup4(uv, fp, kMomentLodBias);
        const float second = cross_moment->lookup4(uv, fp, kMomentLodBias).x;
        cov.z = second - first.x * first.y;
    }
    if (t < 1.0f) blend_surface(uv, *fp, t, true, mean, cov);
    // Kept where Σ stays positive semi-definite.
    const float bound = std::sqrt(s.covariance.x * s.covariance.y);
    return std::clamp(cov.z, -bound, bound);
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
