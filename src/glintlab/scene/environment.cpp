#include "glintlab/scene/environment.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "glintlab/core/error.h"

namespace glintlab {

EnvironmentMap::EnvironmentMap(Image image, float scale, float rotation_deg)
    : image_(std::move(image)),
      scale_(scale),
      rotation_deg_(rotation_deg),
      rotation_rad_(glm::radians(rotation_deg)) {
    const int w = image_.width, h = image_.height;
    if (w <= 0 || h <= 0) fail("environment map has no pixels");
    // The sampling grid refines the image so that it has at least 64 rows:
    // the density is piecewise constant per grid cell and the sinθ factor
    // varies within a row, so coarse maps (down to a constant 1x1) would
    // otherwise be sampled far from proportionally to their solid angle.
    const int fy = std::max(1, (64 + h - 1) / h), fx = std::max(1, (128 + w - 1) / w);
    const int gw = w * fx, gh = h * fy;
    // Weight of a grid cell: the largest luminance in its texel's 3x3
    // neighbourhood (the support of bilinear lookups), times sinθ of the cell
    // row (the lat-long area element). Taking the max keeps pdf > 0 wherever
    // the bilinear radiance is > 0, so light sampling alone is unbiased.
    std::vector<float> texel_weight(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float m = 0.0f;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int yy = std::clamp(y + dy, 0, h - 1);
                    const int xx = (x + dx + w) % w;
                    m = std::max(m, luminance(image_.at(xx, yy)));
                }
            texel_weight[static_cast<size_t>(y) * w + x] = m;
        }
    std::vector<float> weights(static_cast<size_t>(gw) * gh);
    for (int y = 0; y < gh; ++y) {
        const float sin_theta =
            std::sin(glm::pi<float>() * (static_cast<float>(y) + 0.5f) / static_cast<float>(gh));
        for (int x = 0; x < gw; ++x)
            weights[static_cast<size_t>(y) * gw + x] =
                texel_weight[static_cast<size_t>(y / fy) * w + x / fx] * sin_theta;
    }
    distribution_ = Distribution2D(weights, gw, gh);
}

EnvironmentMap EnvironmentMap::constant(glm::vec3 radiance) {
    return EnvironmentMap(Image(1, 1, radiance), 1.0f, 0.0f);
}

glm::vec2 EnvironmentMap::direction_to_uv(glm::vec3 d) const {
    const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
    float phi = std::atan2(d.x, -d.z) - rotation_rad_;
    float u = 0.5f + phi * glm::one_over_two_pi<float>();
    u -= std::floor(u);
    return {u, theta * glm::one_over_pi<float>()};
}

glm::vec3 EnvironmentMap::uv_to_direction(glm::vec2 uv) const {
    const float theta = uv.y * glm::pi<float>();
    const float phi = (uv.x - 0.5f) * glm::two_pi<float>() + rotation_rad_;
    const float s = std::sin(theta);
    return {s * std::sin(phi), std::cos(theta), -s * std::cos(phi)};
}

glm::vec3 EnvironmentMap::eval(glm::vec3 dir) const {
    const glm::vec2 uv = direction_to_uv(dir);
    const int w = image_.width, h = image_.height;
    const float fx = uv.x * static_cast<float>(w) - 0.5f;
    const float fy = uv.y * static_cast<float>(h) - 0.5f;
    const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
    const float tx = fx - static_cast<float>(x0), ty = fy - static_cast<float>(y0);
    auto texel = [&](int x, int y) { return image_.at((x % w + w) % w, std::clamp(y, 0, h - 1)); };
    const glm::vec3 top = glm::mix(texel(x0, y0), texel(x0 + 1, y0), tx);
    const glm::vec3 bottom = glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), tx);
    return scale_ * glm::mix(top, bottom, ty);
}

glm::vec3 EnvironmentMap::sample(glm::vec2 u, glm::vec3* dir, float* pdf) const {
    float map_pdf = 0.0f;
    const glm::vec2 uv = distribution_.sample(u, &map_pdf);
    const float sin_theta = std::sin(uv.y * glm::pi<float>());
    *dir = uv_to_direction(uv);
    // Change of variables from the unit square to solid angle: dω = 2π² sinθ du dv.
    *pdf = sin_theta > 0.0f ? map_pdf / (2.0f * glm::pi<float>() * glm::pi<float>() * sin_theta)
                            : 0.0f;
    return eval(*dir);
}

float EnvironmentMap::pdf(glm::vec3 dir) const {
    const glm::vec2 uv = direction_to_uv(dir);
    const float sin_theta = std::sin(uv.y * glm::pi<float>());
    if (sin_theta <= 0.0f) return 0.0f;
    return distribution_.pdf(uv) / (2.0f * glm::pi<float>() * glm::pi<float>() * sin_theta);
}

}  // namespace glintlab
