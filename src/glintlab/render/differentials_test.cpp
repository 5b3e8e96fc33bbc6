// Footprints from ray differentials against closed-form values for a pinhole
// camera looking at a plane.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/accel.h"
#include "glintlab/render/differentials.h"

namespace glintlab {
namespace {

constexpr float kSize = 40.0f;  // quad side: large enough for grazing views

Scene plane_scene(float distance, float tilt_deg, float fov_deg, int res) {
    // A kSize² quad (uv = x/kSize + 1/2, −z/kSize + 1/2) seen from `distance` along a
    // direction tilted by tilt_deg from the normal (+y), towards +z.
    const float t = glm::radians(tilt_deg);
    nlohmann::json j = {
        {"film", {{"width", res}, {"height", res}}},
        {"camera",
         {{"eye", {0.0f, distance * std::cos(t), distance * std::sin(t)}},
          {"target", {0, 0, 0}},
          {"up", {0, 1, 0}},
          {"fov_deg", fov_deg}}},
        {"materials", {{{"name", "m"}, {"type", "diffuse"}}}},
        {"shapes", {{{"type", "quad"}, {"size", {kSize, kSize}}, {"material", "m"}}}},
    };
    if (tilt_deg == 0.0f) j["camera"]["up"] = {0, 0, -1};
    return parse_scene(j, "test.json");
}

// Exact uv where a camera ray meets the plane y = 0.
glm::vec2 exact_uv(const Ray& r) {
    const float t = -r.o.y / r.d.y;
    const glm::vec3 p = r.o + t * r.d;
    return {p.x / kSize + 0.5f, -p.z / kSize + 0.5f};
}

TEST(Footprint, HeadOnPlaneMatchesPixelSize) {
    const float distance = 3.0f, fov = 30.0f;
    const int res = 64;
    const Scene scene = plane_scene(distance, 0.0f, fov, res);
    const Accelerator accel(scene);
    const RayDifferential ray =
        scene.camera.generate({32.0f, 32.0f});  // pixel corner at the centre
    const auto hit = accel.intersect(ray.ray, 1e30f);
    ASSERT_TRUE(hit);
    const SurfaceDifferentials d = compute_differentials(ray, *hit);
    // One pixel spans 2·distance·tan(fov/2)/res world units at the optical
    // axis; the quad maps kSize world units to 1 in uv. Camera right = +x (u),
    // image down = +z (−v).
    const float pixel = 2.0f * distance * std::tan(glm::radians(fov) / 2.0f) / res;
    EXPECT_NEAR(d.footprint.duvdx.x, pixel / kSize, 1e-6f);
    EXPECT_NEAR(d.footprint.duvdx.y, 0.0f, 1e-6f);
    EXPECT_NEAR(d.footprint.duvdy.x, 0.0f, 1e-6f);
    EXPECT_NEAR(d.footprint.duvdy.y, -pixel / kSize, 1e-6f);
    EXPECT_NEAR(d.footprint.uv.x, 0.5f, 1e-5f);
    EXPECT_NEAR(d.footprint.uv.y, 0.5f, 1e-5f);
}

TEST(Footprint, TiltedPlaneMatchesExactNeighbourRays) {
    // On a plane the tangent plane is the surface itself, so the differential
    // footprint equals the exact uv difference to the neighbouring pixel's ray.
    for (float tilt : {20.0f, 50.0f, 75.0f}) {
        const Scene scene = plane_scene(2.5f, tilt, 40.0f, 128);
        const Accelerator accel(scene);
        for (glm::vec2 px :
             {glm::vec2(64.5f, 64.5f), glm::vec2(20.5f, 90.5f), glm::vec2(100.5f, 30.5f)}) {
            const RayDifferential ray = scene.camera.generate(px);
            const auto hit = accel.intersect(ray.ray, 1e30f);
            ASSERT_TRUE(hit) << tilt;
            const SurfaceDifferentials d = compute_differentials(ray, *hit);
            const glm::vec2 uv0 = exact_uv(ray.ray);
            const glm::vec2 ex = exact_uv(ray.rx) - uv0, ey = exact_uv(ray.ry) - uv0;
            // fp32 ray/plane intersections: relative error ~1e-5 of the footprint.
            const float tol = 2e-4f * std::max(glm::length(ex), glm::length(ey));
            EXPECT_NEAR(d.footprint.duvdx.x, ex.x, tol) << tilt;
            EXPECT_NEAR(d.footprint.duvdx.y, ex.y, tol) << tilt;
            EXPECT_NEAR(d.footprint.duvdy.x, ey.x, tol) << tilt;
            EXPECT_NEAR(d.footprint.duvdy.y, ey.y, tol) << tilt;
            EXPECT_NEAR(d.footprint.uv.x, uv0.x, 1e-4f);
            EXPECT_NEAR(d.footprint.uv.y, uv0.y, 1e-4f);
        }
        // Grazing views stretch the footprint along the view direction (v):
        // at the centre it grows like 1/cos(tilt) relative to the u extent (to
        // first order in the pixel angle δ ≈ 0.0057: the finite step adds ~δ·tan(tilt) ≤ 2.2 %).
        const RayDifferential c = scene.camera.generate({64.0f, 64.0f});
        const SurfaceDifferentials d = compute_differentials(c, *accel.intersect(c.ray, 1e30f));
        EXPECT_NEAR(std::abs(d.footprint.duvdy.y) / std::abs(d.footprint.duvdx.x),
                    1.0f / std::cos(glm::radians(tilt)), 0.05f / std::cos(glm::radians(tilt)))
            << tilt;
    }
}

TEST(Footprint, SphereUvDerivativesAreAnalytic) {
    nlohmann::json j = {
        {"film", {{"width", 32}, {"height", 32}}},
        {"camera", {{"eye", {0, 0, 5}}, {"target", {0, 0, 0}}, {"fov_deg", 30}}},
        {"materials", {{{"name", "m"}, {"type", "diffuse"}}}},
        {"shapes", {{{"type", "sphere"}, {"radius", 1.0}, {"material", "m"}}}},
    };
    const Scene scene = parse_scene(j, "test.json");
    const Accelerator accel(scene);
    const RayDifferential ray = scene.camera.generate({16.0f, 16.0f});
    const auto hit = accel.intersect(ray.ray, 1e30f);
    ASSERT_TRUE(hit);
    // Hit at (0,0,1): θ = π/2, φ = π/2 → uv = (0.25, 0.5); ∂p/∂u = 2π r (−1,0,0), ∂p/∂v = π r
    // (0,−1,0).
    EXPECT_NEAR(hit->uv.x, 0.25f, 1e-5f);
    EXPECT_NEAR(hit->uv.y, 0.5f, 1e-5f);
    EXPECT_NEAR(hit->dpdu.x, -2.0f * glm::pi<float>(), 1e-4f);
    EXPECT_NEAR(hit->dpdv.y, -glm::pi<float>(), 1e-4f);
    const SurfaceDifferentials d = compute_differentials(ray, *hit);
    // Pixel size at distance 4 (the sphere's front): 2·4·tan(15°)/32 world
    // units; du = −dx/(2π), dv = +dy_world_down/π.
    const float pixel = 2.0f * 4.0f * std::tan(glm::radians(15.0f)) / 32.0f;
    EXPECT_NEAR(d.footprint.duvdx.x, -pixel / (2.0f * glm::pi<float>()), 2e-6f);
    EXPECT_NEAR(d.footprint.duvdy.y, pixel / glm::pi<float>(), 2e-6f);
}

}  // namespace
}  // namespace glintlab

namespace glintlab {
namespace {

TEST(Footprint, OrthographicFootprintIsConstantAcrossTheImage) {
    // An orthographic view of height H at resolution R: every pixel spans H/R
    // world units, whatever its position, so the uv footprint is constant.
    nlohmann::json j = {
        {"film", {{"width", 40}, {"height", 20}}},
        {"camera",
         {{"type", "orthographic"},
          {"eye", {0, 5, 0}},
          {"target", {0, 0, 0}},
          {"up", {0, 0, -1}},
          {"height", 2.0}}},
        {"materials", {{{"name", "m"}, {"type", "diffuse"}}}},
        {"shapes", {{{"type", "quad"}, {"size", {8, 8}}, {"uv_scale", {2, 2}}, {"material", "m"}}}},
    };
    const Scene scene = parse_scene(j, "test.json");
    const Accelerator accel(scene);
    const float pixel = 2.0f / 20.0f;
    for (glm::vec2 px : {glm::vec2(0.5f, 0.5f), glm::vec2(20.5f, 10.5f), glm::vec2(39.5f, 19.5f)}) {
        const RayDifferential ray = scene.camera.generate(px);
        const auto hit = accel.intersect(ray.ray, 1e30f);
        ASSERT_TRUE(hit);
        const SurfaceDifferentials d = compute_differentials(ray, *hit);
        // uv_scale 2 over 8 world units: du/dx = pixel · 2/8.
        EXPECT_NEAR(d.footprint.duvdx.x, pixel * 0.25f, 1e-6f);
        EXPECT_NEAR(d.footprint.duvdy.y, -pixel * 0.25f, 1e-6f);
        EXPECT_NEAR(d.footprint.duvdx.y, 0.0f, 1e-6f);
        EXPECT_NEAR(d.footprint.duvdy.x, 0.0f, 1e-6f);
    }
}

}  // namespace
}  // namespace glintlab
