#include "glintlab/validate/random_queries.h"

#include <algorithm>
#include <cmath>

namespace glintlab {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

Footprint oriented_footprint(glm::vec2 uv, double minor, double ratio, double angle) {
    const glm::vec2 major_dir(static_cast<float>(std::cos(angle)),
                              static_cast<float>(std::sin(angle)));
    Footprint fp;
    fp.uv = uv;
    fp.duvdx = major_dir * static_cast<float>(minor * ratio);
    fp.duvdy = glm::vec2(-major_dir.y, major_dir.x) * static_cast<float>(minor);
    return fp;
}

glm::vec3 half_vector_at(double tan_theta, double phi) {
    const double c = 1.0 / std::sqrt(1.0 + tan_theta * tan_theta);
    const double s = tan_theta * c;
    return glm::vec3(static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)),
                     static_cast<float>(c));
}

double pow10_uniform(Pcg32& rng, double lo_exp10, double hi_exp10) {
    return std::pow(10.0, lo_exp10 + (hi_exp10 - lo_exp10) * rng.next_double());
}

RobustnessQuery draw_robustness_query(Pcg32& rng) {
    RobustnessQuery q;
    const uint32_t hk = rng.next_uint(8);
    if (hk == 0) {
        q.h = glm::vec3(0.0f, 0.0f, 1.0f);
    } else if (hk == 1) {
        q.h = glm::normalize(glm::vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f,
                                       static_cast<float>(pow10_uniform(rng, -30, -3))));
    } else {
        const double z = 2.0 * rng.next_double() - 1.0, phi = 2.0 * kPi * rng.next_double();
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        q.h = glm::vec3(static_cast<float>(r * std::cos(phi)),
                        static_cast<float>(r * std::sin(phi)), static_cast<float>(z));
    }
    const float su = rng.next_float() < 0.5f ? -1.0f : 1.0f;
    const glm::vec2 uv(su * static_cast<float>(pow10_uniform(rng, -4, 7)),
                       static_cast<float>(pow10_uniform(rng, -4, 7)));
    q.footprint = oriented_footprint(uv, pow10_uniform(rng, -25, 15), pow10_uniform(rng, 0, 12),
                                     rng.next_double() * 2.0 * kPi);
    const uint32_t fk = rng.next_uint(10);
    if (fk == 0)
        q.footprint.duvdx = q.footprint.duvdy = glm::vec2(0.0f);
    else if (fk == 1)
        q.footprint.duvdy = q.footprint.duvdx * (rng.next_float() - 0.5f);
    else if (fk == 2)
        q.footprint.duvdy = glm::vec2(0.0f);
    q.ndf = static_cast<int>(rng.next_uint(2));
    q.alpha_x = static_cast<float>(pow10_uniform(rng, -3, 0));
    q.alpha_y = rng.next_float() < 0.5f ? q.alpha_x : static_cast<float>(pow10_uniform(rng, -3, 0));
    const uint32_t dk = rng.next_uint(4);
    q.log_density = dk == 0 ? -20.0f : dk == 1 ? 60.0f : -20.0f + 80.0f * rng.next_float();
    q.seed = rng.next_uint();
    return q;
}

}  // namespace glintlab
