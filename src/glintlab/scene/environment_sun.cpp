#include "glintlab/scene/environment_sun.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

constexpr double kPi = std::numbers::pi;

glm::vec3 map_direction(double u, double v) {
    const double theta = v * kPi, phi = (u - 0.5) * 2.0 * kPi;
    const double s = std::sin(theta);
    return glm::vec3(glm::dvec3(s * std::sin(phi), std::cos(theta), -s * std::cos(phi)));
}

}  // namespace

EnvironmentSunSplit split_environment_sun(const Image& map, int samples) {
    if (samples < 1) fail("environment sun: at least one sample is needed, got {}", samples);
    const int w = map.width, h = map.height;
    EnvironmentSunSplit split{map, {}, {}};
    if (w < 1 || h < 1) return split;
    std::vector<double> texel_omega(static_cast<size_t>(h));
    for (int y = 0; y < h; ++y)
        texel_omega[size_t(y)] =
            2.0 * kPi / w * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));
    double power = 0.0;
    int peak_x = 0, peak_y = 0;
    float peak = -1.0f;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float l = luminance(map.at(x, y));
            power += texel_omega[size_t(y)] * l;
            if (l > peak) peak = l, peak_x = x, peak_y = y;
        }
    const double mean = power / (4.0 * kPi);
    if (!(peak > EnvironmentSunCriteria::kContrast * mean)) return split;
    const double threshold = std::max(double(EnvironmentSunCriteria::kFraction) * peak,
                                      double(EnvironmentSunCriteria::kContrast) * mean);
    const glm::vec3 centre = map_direction((peak_x + 0.5) / w, (peak_y + 0.5) / h);
    const double cos_cone = std::cos(EnvironmentSunCriteria::kConeDeg * kPi / 180.0);
    struct Texel {
        int x, y;
        double power;  // luminance × solid angle
    };
    std::vector<Texel> sun;
    double sun_power = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float l = luminance(map.at(x, y));
            if (l < threshold) continue;
            if (glm::dot(map_direction((x + 0.5) / w, (y + 0.5) / h), centre) < cos_cone) continue;
            sun.push_back({x, y, texel_omega[size_t(y)] * (l - threshold)});
            sun_power += sun.back().power;
        }
    if (!(sun_power > 0.0)) return split;  // a flat top: nothing above the threshold
    size_t j = 0;
    double below = 0.0;  // power of the texels before sun[j]
    for (int k = 0; k < samples; ++k) {
        const double q = (k + 0.5) / samples * sun_power;
        while (j + 1 < sun.size() && below + sun[j].power <= q) below += sun[j++].power;
        const Texel& t = sun[j];
        const double frac = std::clamp((q - below) / t.power, 0.0, 1.0);
        split.directions.push_back(map_direction((t.x + frac) / w, (t.y + 0.5) / h));
        const glm::vec3 c = map.at(t.x, t.y);
        split.powers.push_back(c / luminance(c) * float(sun_power / samples));
    }
    for (const Texel& t : sun) {
        glm::vec3& c = split.residual.at(t.x, t.y);
        c *= float(threshold) / luminance(c);
    }
    return split;
}

}  // namespace glintlab
