#include "glintlab/scene/environment_sun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace glintlab {
namespace {

constexpr double kPi = std::numbers::pi;

// Luminance power (Σ L Ω) of a lat-long image.
double power_of(const Image& img) {
    double p = 0.0;
    for (int y = 0; y < img.height; ++y) {
        const double omega =
            2.0 * kPi / img.width *
            (std::cos(kPi * y / img.height) - std::cos(kPi * (y + 1) / img.height));
        for (int x = 0; x < img.width; ++x) p += omega * luminance(img.at(x, y));
    }
    return p;
}

// A 2x2-texel sun 10 degrees from the zenith on a dim sky: it is found, its
// texels leave the residual, the samples lie in it and carry its power, so
// residual + samples keep the map's power; a dim map has no sun.
TEST(EnvironmentSun, SplitKeepsThePowerAndPutsTheSamplesInTheSun) {
    Image map(128, 64, glm::vec3(0.2f, 0.3f, 0.4f));
    const int sx = 40, sy = 3;  // theta = (3.5 / 64) 180 = 9.8 deg
    for (int y = sy; y < sy + 2; ++y)
        for (int x = sx; x < sx + 2; ++x) map.at(x, y) = glm::vec3(3000.0f, 2800.0f, 2500.0f);
    const EnvironmentSunSplit split = split_environment_sun(map, 16);
    ASSERT_EQ(split.directions.size(), 16u);
    ASSERT_EQ(split.powers.size(), 16u);
    double sample_power = 0.0;
    const double theta = kPi * (sy + 1.0) / 64, phi = ((sx + 1.0) / 128 - 0.5) * 2.0 * kPi;
    const glm::vec3 centre(std::sin(theta) * std::sin(phi), std::cos(theta),
                           -std::sin(theta) * std::cos(phi));
    for (size_t k = 0; k < 16; ++k) {
        sample_power += luminance(split.powers[k]);
        // Within the 2x2 texels: 2.8 deg of theta, less in phi at this latitude.
        EXPECT_GT(glm::dot(split.directions[k], centre), std::cos(2.5 * kPi / 180.0)) << k;
        EXPECT_NEAR(split.powers[k].x / split.powers[k].z, 3000.0 / 2500.0, 1e-4) << k;
    }
    EXPECT_NEAR(power_of(split.residual) + sample_power, power_of(map), 1e-5 * power_of(map));
    // The sun's texels keep their colour at the threshold, max(5 % of the
    // peak, 50x the mean) = 5 % of 2842 here.
    EXPECT_NEAR(luminance(split.residual.at(sx, sy)), 0.05f * luminance(map.at(sx, sy)), 1e-2f);
    EXPECT_NEAR(split.residual.at(sx, sy).x / split.residual.at(sx, sy).z, 3000.0 / 2500.0, 1e-4);
    EXPECT_EQ(split.residual.at(0, 32), map.at(0, 32));

    Image dim(128, 64, glm::vec3(0.5f));
    dim.at(5, 30) = glm::vec3(20.0f);  // 40x the mean: not a sun (kContrast = 50)
    const EnvironmentSunSplit none = split_environment_sun(dim, 16);
    EXPECT_TRUE(none.directions.empty());
    EXPECT_EQ(none.residual.pixels, dim.pixels);
}

}  // namespace
}  // namespace glintlab
