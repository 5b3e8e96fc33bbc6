#include "glintlab/scene/environment_sources.h"

#include <gtest/gtest.h>

#include <algorithm>
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

double sample_power(const EnvironmentSourceSplit& split) {
    double p = 0.0;
    for (const glm::vec3& c : split.powers) p += luminance(c);
    return p;
}

// Direction of texel coordinates (x, y) (continuous, texel corners at
// integers), as EnvironmentMap::uv_to_direction at rotation 0.
glm::vec3 direction(double x, double y, const Image& map) {
    const double theta = kPi * y / map.height, phi = (x / map.width - 0.5) * 2.0 * kPi;
    return glm::vec3(std::sin(theta) * std::sin(phi), std::cos(theta),
                     -std::sin(theta) * std::cos(phi));
}

// The angle (degrees) between a sample and the centre of a block of texels.
double degrees_from(glm::vec3 d, double cx, double cy, const Image& map) {
    return std::acos(std::clamp(double(glm::dot(d, direction(cx, cy, map))), -1.0, 1.0)) * 180.0 /
           kPi;
}

void fill_block(Image& map, int x0, int y0, int size, glm::vec3 c) {
    for (int y = y0; y < y0 + size; ++y)
        for (int x = x0; x < x0 + size; ++x) map.at((x + map.width) % map.width, y) = c;
}

// A 2x2-texel sun 10 degrees from the zenith on a uniform sky: it is found,
// its texels come down to the sky's radiance in the residual, the samples
// lie in it and carry its power in its colour, so residual + samples keep
// the map's power, each standing for a 16th of its 4 texels' solid angle
// (a disc of that area: the radius); a dim map has no source.
TEST(EnvironmentSources, SplitKeepsThePowerAndPutsTheSamplesInTheSun) {
    const glm::vec3 sky(0.2f, 0.3f, 0.4f), sun(3000.0f, 2800.0f, 2500.0f);
    Image map(128, 64, sky);
    const int sx = 40, sy = 3;  // theta = (4 / 64) 180 = 11.25 deg
    fill_block(map, sx, sy, 2, sun);
    const EnvironmentSourceSplit split = split_environment_sources(map, 16);
    ASSERT_EQ(split.directions.size(), 16u);
    ASSERT_EQ(split.powers.size(), 16u);
    ASSERT_EQ(split.radii.size(), 16u);
    // Rows 3 and 4 of 64: solid angle 2 (2 pi / 128) (cos(3 pi / 64) - cos(5 pi / 64)).
    const double sun_omega =
        2.0 * 2.0 * kPi / 128.0 * (std::cos(3.0 * kPi / 64.0) - std::cos(5.0 * kPi / 64.0));
    for (size_t k = 0; k < 16; ++k) {
        EXPECT_NEAR(split.radii[k], std::sqrt(sun_omega / (16.0 * kPi)), 1e-6) << k;
        // Within the 2x2 texels: 2.8 deg of theta either side, 0.6 of phi.
        EXPECT_LT(degrees_from(split.directions[k], sx + 1.0, sy + 1.0, map), 3.0) << k;
        const glm::vec3 excess = sun - sky;
        EXPECT_NEAR(split.powers[k].x / split.powers[k].z, excess.x / excess.z, 1e-4) << k;
    }
    EXPECT_NEAR(power_of(split.residual) + sample_power(split), power_of(map),
                1e-5 * power_of(map));
    for (int y = sy; y < sy + 2; ++y)
        for (int x = sx; x < sx + 2; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(split.residual.at(x, y)[c], sky[c], 1e-5f);
    EXPECT_EQ(split.residual.at(0, 32), map.at(0, 32));

    Image dim(128, 64, glm::vec3(0.5f));
    dim.at(5, 30) = glm::vec3(20.0f);  // 40x the mean: not a source (kContrast = 50)
    const EnvironmentSourceSplit none = split_environment_sources(dim, 16);
    EXPECT_TRUE(none.directions.empty());
    EXPECT_EQ(none.residual.pixels, dim.pixels);
}

// Three lamps near the horizon of a studio-like map, powers 3 : 1 : 0.02.
// The first two get samples in proportion (12 and 4 of 16), each inside its
// own lamp, spread over it (not all on one row); the third holds less than
// half a sample's power and stays in the residual untouched. One lamp
// straddles the map's u seam and is one source. Power is kept.
TEST(EnvironmentSources, LampsGetSamplesByTheirPowerInsideThemselves) {
    const glm::vec3 wall(0.1f);
    Image map(256, 128, wall);
    fill_block(map, 60, 56, 4, glm::vec3(300.0f));   // 16 texels at 300
    fill_block(map, -2, 56, 4, glm::vec3(100.0f));   // across the seam: x 254, 255, 0, 1
    fill_block(map, 180, 60, 1, glm::vec3(128.0f));  // one texel: 1/37.5 of the rest
    const EnvironmentSourceSplit split = split_environment_sources(map, 16);
    ASSERT_EQ(split.directions.size(), 16u);
    int in_first = 0, in_second = 0;
    double y_min = 1e9, y_max = -1e9;
    for (size_t k = 0; k < 16; ++k) {
        const glm::vec3 d = split.directions[k];
        if (degrees_from(d, 62.0, 58.0, map) < 4.2) {
            ++in_first;
            y_min = std::min(y_min, double(std::acos(d.y)));
            y_max = std::max(y_max, double(std::acos(d.y)));
        } else if (degrees_from(d, 0.0, 58.0, map) < 4.2) {
            ++in_second;
        }
    }
    EXPECT_EQ(in_first, 12);
    EXPECT_EQ(in_second, 4);
    // The first lamp's samples span at least half of its 4 rows (5.6 deg).
    EXPECT_GT((y_max - y_min) * 180.0 / kPi, 2.8);
    EXPECT_EQ(split.residual.at(180, 60), map.at(180, 60));
    EXPECT_NEAR(luminance(split.residual.at(61, 57)), 0.1f, 1e-5f);
    EXPECT_NEAR(luminance(split.residual.at(255, 57)), 0.1f, 1e-5f);
    EXPECT_NEAR(power_of(split.residual) + sample_power(split), power_of(map),
                1e-5 * power_of(map));
}

// A lamp whose surroundings are brighter in one channel than the lamp
// itself: the residual keeps the lamp's value in that channel (never above
// the texel) and the sample's power carries the rest, so every channel's
// power is kept and no power is negative.
TEST(EnvironmentSources, ResidualNeverExceedsTheTexel) {
    Image map(128, 64, glm::vec3(0.0f, 0.0f, 2.0f));
    fill_block(map, 30, 30, 2, glm::vec3(400.0f, 400.0f, 1.0f));
    const EnvironmentSourceSplit split = split_environment_sources(map, 8);
    ASSERT_EQ(split.directions.size(), 8u);
    EXPECT_FLOAT_EQ(split.residual.at(30, 30).z, 1.0f);
    glm::dvec3 samples(0.0);
    for (const glm::vec3& c : split.powers) {
        EXPECT_GE(std::min({c.x, c.y, c.z}), 0.0f);
        samples += glm::dvec3(c);
    }
    EXPECT_NEAR(samples.z, 0.0, 1e-9);
    EXPECT_GT(samples.x, 0.0);
}

}  // namespace
}  // namespace glintlab
