#include "glintlab/core/normal_map.h"

#include <algorithm>
#include <cmath>

namespace glintlab {

glm::vec3 SlopeStatistics::normal() const {
    return glm::normalize(glm::vec3(-mean.x, -mean.y, 1.0f));
}

SlopeStatistics NormalMap::lookup(glm::vec2 uv, const Footprint* footprint) const {
    const Footprint* fp = filtering == Filtering::Lean ? footprint : nullptr;
    SlopeStatistics s;
    const glm::vec3 first = slopes->lookup(uv, fp);
    s.mean = glm::vec2(first.x, first.y);
    if (!fp) return s;  // one point of the bilinear surface: no spread to keep
    const glm::vec3 second = moments->lookup(uv, fp);
    // Σ = E[s sᵀ] − s̄ s̄ᵀ; rounding can leave it slightly indefinite.
    float xx = std::max(second.x - s.mean.x * s.mean.x, 0.0f);
    float yy = std::max(second.y - s.mean.y * s.mean.y, 0.0f);
    const float bound = std::sqrt(xx * yy);
    const float xy = std::clamp(second.z - s.mean.x * s.mean.y, -bound, bound);
    s.covariance = glm::vec3(xx, yy, xy);
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
