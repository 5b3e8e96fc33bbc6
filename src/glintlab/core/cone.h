// Cones of directions carried by 1 − cos θmax instead of cos θmax: a cone of
// solid angle below ~1.5e-7 sr (a star, a sphere light 1e4 radii away) has
// cos θmax = 1 in single precision, so a test `dot(d, axis) >= cos_max`
// misses it and its pdf 1 / (2π (1 − cos θmax)) is infinite.
#pragma once

#include <algorithm>

#include <glm/glm.hpp>

namespace glintlab {

// 1 − cos θ from sin²θ (θ ≤ π/2), without the cancellation of 1 − √(1 − s).
inline float one_minus_cos_from_sin2(float sin2) {
    const float s = std::clamp(sin2, 0.0f, 1.0f);
    return s / (1.0f + std::sqrt(1.0f - s));
}

// Whether unit direction d lies in the cone of unit axis `axis` with
// 1 − cos θmax = one_minus_cos_max; for nearly parallel vectors 1 − cos is
// taken from |d × axis|² / (1 + cos), exact where 1 − dot would round to 0.
inline bool inside_cone(glm::vec3 d, glm::vec3 axis, float one_minus_cos_max) {
    const float c = glm::dot(d, axis);
    if (c <= 0.0f) return 1.0f - c <= one_minus_cos_max;
    const glm::vec3 x = glm::cross(d, axis);
    return glm::dot(x, x) / (1.0f + c) <= one_minus_cos_max;
}

}  // namespace glintlab
