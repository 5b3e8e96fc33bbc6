#include <gtest/gtest.h>

#include <cmath>

#include "glintlab/realtime/orbit_camera.h"

namespace glintlab {
namespace {

Camera start() {
    Camera c;
    c.eye = {0.0f, 1.0f, 3.0f};
    c.target = {0.5f, 0.0f, 0.0f};
    c.up = {0.0f, 1.0f, 0.0f};
    return c;
}

TEST(OrbitCamera, OrbitKeepsTheDistanceAndTarget) {
    Camera c = start();
    const float d0 = glm::length(c.eye - c.target);
    orbit_camera(c, {37.0f, -12.0f}, {0.0f, 0.0f}, 0.0);
    EXPECT_NEAR(glm::length(c.eye - c.target), d0, 1e-5f);
    EXPECT_EQ(c.target, start().target);
    EXPECT_GT(glm::length(c.eye - start().eye), 0.1f);
}

TEST(OrbitCamera, HorizontalDragRotatesAboutUp) {
    Camera c = start();
    // pi / 2 about +y (0.01 rad per pixel, negative sign: drag right turns left).
    orbit_camera(c, {-157.07963f, 0.0f}, {0.0f, 0.0f}, 0.0);
    const glm::vec3 o = c.eye - c.target;
    EXPECT_NEAR(o.y, 1.0f, 1e-5f);  // height above the target unchanged
    EXPECT_NEAR(o.x, 3.0f, 1e-4f);  // (x, z) = (-0.5, 3) turned by 90 deg about +y
    EXPECT_NEAR(o.z, 0.5f, 1e-4f);
}

TEST(OrbitCamera, NeverCrossesThePole) {
    Camera c = start();
    for (int i = 0; i < 100; ++i) orbit_camera(c, {0.0f, 50.0f}, {0.0f, 0.0f}, 0.0);
    const glm::vec3 o = glm::normalize(c.eye - c.target);
    EXPECT_LT(std::abs(o.y), 0.995f + 1e-4f);
    EXPECT_TRUE(std::isfinite(o.x) && std::isfinite(o.y) && std::isfinite(o.z));
}

TEST(OrbitCamera, PanMovesEyeAndTargetTogetherAndDollyScales) {
    Camera c = start();
    const glm::vec3 offset = c.eye - c.target;
    orbit_camera(c, {0.0f, 0.0f}, {10.0f, 5.0f}, 0.0);
    EXPECT_NEAR(glm::length((c.eye - c.target) - offset), 0.0f, 1e-5f);
    EXPECT_GT(glm::length(c.target - start().target), 0.0f);
    orbit_camera(c, {0.0f, 0.0f}, {0.0f, 0.0f}, 2.0);
    EXPECT_NEAR(glm::length(c.eye - c.target), 0.81f * glm::length(offset), 1e-4f);
}

TEST(OrbitCamera, LookingAlongUpStaysFinite) {
    Camera c;
    c.eye = {0.0f, 3.0f, 0.0f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.up = {0.0f, 1.0f, 0.0f};
    orbit_camera(c, {10.0f, 10.0f}, {4.0f, 4.0f}, 1.0);
    EXPECT_TRUE(std::isfinite(c.eye.x) && std::isfinite(c.eye.y) && std::isfinite(c.eye.z));
    EXPECT_TRUE(std::isfinite(c.target.x) && std::isfinite(c.target.y) &&
                std::isfinite(c.target.z));
}

}  // namespace
}  // namespace glintlab
