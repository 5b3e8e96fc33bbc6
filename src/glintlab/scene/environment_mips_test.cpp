#include "glintlab/scene/environment_mips.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <tuple>

namespace glintlab {
namespace {

// The exact solid-angle mean of a lat-long image (row weight cos θ0 − cos θ1).
glm::dvec3 solid_angle_mean(const Image& img) {
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (int y = 0; y < img.height; ++y) {
        const double w = std::cos(std::numbers::pi * y / img.height) -
                         std::cos(std::numbers::pi * (y + 1) / img.height);
        for (int x = 0; x < img.width; ++x) sum += w * glm::dvec3(img.at(x, y)), weight += w;
    }
    return sum / weight;
}

TEST(LatlongMipChain, SizesFollowOpenGLsChain) {
    const std::vector<Image> chain = latlong_mip_chain(Image(20, 6, glm::vec3(1.0f)));
    const int expected[][2] = {{20, 6}, {10, 3}, {5, 1}, {2, 1}, {1, 1}};
    ASSERT_EQ(chain.size(), std::size(expected));
    for (size_t k = 0; k < chain.size(); ++k) {
        EXPECT_EQ(chain[k].width, expected[k][0]) << k;
        EXPECT_EQ(chain[k].height, expected[k][1]) << k;
        for (const glm::vec3& p : chain[k].pixels) EXPECT_FLOAT_EQ(p.y, 1.0f) << k;
    }
}

// Every level keeps the map's solid-angle mean (the power of the lighting),
// power-of-two or not (to float rounding); a sun near the zenith keeps its
// share instead of the 1/sin θ-fold one that equal weights give it.
TEST(LatlongMipChain, EveryLevelKeepsTheSolidAngleMean) {
    for (const auto& [w, h, tolerance] : {std::tuple{64, 32, 1e-5}, std::tuple{40, 13, 1e-5}}) {
        SCOPED_TRACE(w);
        Image img(w, h, glm::vec3(0.5f));
        for (int x = 0; x < w; ++x) img.at(x, h - 1) = glm::vec3(0.1f);  // dark ground row
        img.at(w / 3, 1) = glm::vec3(5000.0f, 4000.0f, 3000.0f);         // sun near the zenith
        const glm::dvec3 mean = solid_angle_mean(img);
        const std::vector<Image> chain = latlong_mip_chain(img);
        for (size_t k = 0; k < chain.size(); ++k)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(solid_angle_mean(chain[k])[c], mean[c], tolerance * mean[c]) << k;
        // The equal-weight mean, as glGenerateMipmap's 1x1 level, is far above.
        double plain = 0.0;
        for (const glm::vec3& p : img.pixels) plain += p.x;
        plain /= double(img.pixels.size());
        EXPECT_GT(plain, 1.5 * mean.x);
        EXPECT_NEAR(chain.back().at(0, 0).x, mean.x, tolerance * mean.x);
    }
}

}  // namespace
}  // namespace glintlab
