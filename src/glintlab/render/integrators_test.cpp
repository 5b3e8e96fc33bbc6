// Analytic scenes (pbrt-v4 integrators_test.cpp style): configurations whose
// pixel values are known in closed form, rendered by both integrators.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include <glm/gtc/constants.hpp>

#include "glintlab/core/error.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/renderer.h"

namespace glintlab {
namespace {

struct Stats {
    double mean = 0.0;
    double stderr_mean = 0.0;  // standard error of the mean over pixels
    int count = 0;
};

// Mean of one channel over the pixels inside a centred box.
Stats box_stats(const Image& img, int margin, int channel = 0) {
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    for (int y = margin; y < img.height - margin; ++y)
        for (int x = margin; x < img.width - margin; ++x) {
            const double v = img.at(x, y)[channel];
            sum += v, sum2 += v * v, ++n;
        }
    Stats s;
    s.count = n;
    s.mean = sum / n;
    s.stderr_mean = std::sqrt(std::max(0.0, sum2 / n - s.mean * s.mean) / n);
    return s;
}

nlohmann::json base_scene(const std::string& integrator, int spp) {
    return {{"film", {{"width", 32}, {"height", 32}}},
            {"render", {{"integrator", integrator}, {"spp", spp}, {"seed", 7}, {"max_depth", 8}}},
            {"camera", {{"eye", {0, 0, 5}}, {"target", {0, 0, 0}}, {"fov_deg", 10}}}};
}

class Analytic : public ::testing::TestWithParam<std::string> {};

TEST_P(Analytic, DiffuseSphereInUniformEnvironmentRendersItsAlbedo) {
    // A convex Lambertian surface under uniform radiance 1 reflects
    // ∫ (a/π) cosθ dω = a, whatever the view, in one bounce.
    const float albedo = 0.6f;
    nlohmann::json j = base_scene(GetParam(), 16);
    j["materials"] = {{{"name", "m"}, {"type", "diffuse"}, {"albedo", albedo}}};
    j["shapes"] = {{{"type", "sphere"}, {"radius", 1.0}, {"material", "m"}}};
    j["lights"] = {{{"type", "environment"}, {"radiance", 1.0}}};
    const Image img = render_scene(parse_scene(j, "t.json"), {0, true});
    // fov 10° at distance 5 sees ±0.44: the central 24x24 pixels all hit the sphere.
    const Stats s = box_stats(img, 4);
    // 5σ of the per-pixel MC noise, plus fp32 accumulation slack.
    EXPECT_NEAR(s.mean, albedo, 5.0 * s.stderr_mean + 1e-3) << "σ=" << s.stderr_mean;
}

TEST_P(Analytic, DiffuseQuadUnderDirectionalLight) {
    // E cosθ · a/π for a delta directional light of irradiance E.
    const float albedo = 0.5f, e = 2.0f, theta = glm::radians(30.0f);
    nlohmann::json j = base_scene(GetParam(), 1);
    j["camera"] = {{"eye", {0, 5, 0}}, {"target", {0, 0, 0}}, {"up", {0, 0, -1}}, {"fov_deg", 10}};
    j["materials"] = {{{"name", "m"}, {"type", "diffuse"}, {"albedo", albedo}}};
    j["shapes"] = {{{"type", "quad"}, {"size", {10, 10}}, {"material", "m"}}};
    j["lights"] = {{{"type", "directional"},
                    {"direction", {std::sin(theta), std::cos(theta), 0.0f}},
                    {"irradiance", e}}};
    const Image img = render_scene(parse_scene(j, "t.json"), {0, true});
    const double expected = e * std::cos(theta) * albedo / glm::pi<double>();
    for (const glm::vec3& p : img.pixels) ASSERT_NEAR(p.x, expected, 1e-5 * expected * 10);
    // The same light spread over cones down to the smallest allowed: cones
    // below ~1.5e-7 sr had cos θmax = 1 in float and lit nothing. A direction
    // δ ≤ √(Ω/π) off the axis changes cos θ by at most tan θ δ + δ²/2
    // relative (1.03e-3 at 1e-5 sr); 1e-5 for float rounding.
    for (const double omega : {1e-5, 1.4e-7, 1e-9, 1e-12}) {
        SCOPED_TRACE(omega);
        j["lights"][0]["solid_angle_sr"] = omega;
        const Image cone = render_scene(parse_scene(j, "t.json"), {0, true});
        const double delta = std::sqrt(omega / glm::pi<double>());
        const double tolerance = std::tan(theta) * delta + 0.5 * delta * delta + 1e-5;
        for (const glm::vec3& p : cone.pixels) ASSERT_NEAR(p.x, expected, tolerance * expected);
    }
    j["lights"][0]["solid_angle_sr"] = 1e-13;
    try {
        parse_scene(j, "t.json");
        ADD_FAILURE() << "a cone of 1e-13 sr was accepted";
    } catch (const Error& err) {
        EXPECT_NE(std::string(err.what()).find("0 (a delta light) or [1e-12, 1]"),
                  std::string::npos)
            << err.what();
    }
}

TEST_P(Analytic, DiffuseQuadUnderPointLightFollowsInverseSquare) {
    // Point light of intensity I at height h: L = a/π · I cosθ / r² with cosθ = h/r.
    const float albedo = 0.8f, intensity = 5.0f, h = 2.0f;
    nlohmann::json j = base_scene(GetParam(), 1);
    j["camera"] = {{"eye", {0, 6, 0}}, {"target", {0, 0, 0}}, {"up", {0, 0, -1}}, {"fov_deg", 40}};
    j["materials"] = {{{"name", "m"}, {"type", "diffuse"}, {"albedo", albedo}}};
    j["shapes"] = {{{"type", "quad"}, {"size", {20, 20}}, {"material", "m"}}};
    j["lights"] = {{{"type", "point"}, {"position", {0, h, 0}}, {"intensity", intensity}}};
    const Scene scene = parse_scene(j, "t.json");
    const Image img = render_scene(scene, {0, true});
    for (int y : {0, 8, 16, 31})
        for (int x : {0, 5, 16, 27}) {
            const RayDifferential r = scene.camera.generate({x + 0.5f, y + 0.5f});
            const float t = -r.ray.o.y / r.ray.d.y;
            const glm::vec3 p = r.ray.o + t * r.ray.d;
            const double r2 = p.x * p.x + p.z * p.z + h * h;
            const double expected =
                albedo / glm::pi<double>() * intensity * (h / std::sqrt(r2)) / r2;
            EXPECT_NEAR(img.at(x, y).x, expected, 1e-3 * expected) << x << "," << y;
        }
}

TEST_P(Analytic, SphereLightAboveDiffuseQuad) {
    // A sphere of radiance L, radius r, centre at height d above the shading
    // point gives irradiance E = π L (r/d)² (a cap of half-angle asin(r/d)
    // centred on the normal), so the reflected radiance is a L (r/d)².
    const float albedo = 0.7f, radiance = 4.0f, r = 0.5f, d = 3.0f;
    nlohmann::json j = base_scene(GetParam(), 64);
    j["camera"] = {{"eye", {0, 1.0, 0}}, {"target", {0, 0, 0}}, {"up", {0, 0, -1}}, {"fov_deg", 1}};
    j["materials"] = {{{"name", "m"}, {"type", "diffuse"}, {"albedo", albedo}}};
    j["shapes"] = {{{"type", "quad"}, {"size", {20, 20}}, {"material", "m"}}};
    j["film"] = {{"width", 8}, {"height", 8}};
    j["lights"] = {
        {{"type", "sphere"}, {"center", {0, d, 0}}, {"radius", r}, {"radiance", radiance}}};
    const Image img = render_scene(parse_scene(j, "t.json"), {0, true});
    const Stats s = box_stats(img, 0);
    const double expected = albedo * radiance * (r / d) * (r / d);
    EXPECT_NEAR(s.mean, expected, 5.0 * s.stderr_mean + 1e-3 * expected);
    // A sphere 1e4 radii away (sin²θmax = 1e-8: cos θmax rounds to 1 in float)
    // lights the quad as its cap says.
    const float far_r = 0.01f, far_d = 100.0f, far_l = 1e8f;
    j["lights"] = {
        {{"type", "sphere"}, {"center", {0, far_d, 0}}, {"radius", far_r}, {"radiance", far_l}}};
    const Stats far = box_stats(render_scene(parse_scene(j, "t.json"), {0, true}), 0);
    const double far_expected = albedo * far_l * (far_r / far_d) * (far_r / far_d);
    EXPECT_NEAR(far.mean, far_expected, 5.0 * far.stderr_mean + 1e-3 * far_expected);
}

INSTANTIATE_TEST_SUITE_P(Integrators, Analytic, ::testing::Values("direct", "path"));

TEST(PathIntegrator, InterreflectionBetweenFacingQuadsIsBounded) {
    // Two facing diffuse quads (albedo a) under a uniform environment of
    // radiance 1: light bouncing between them makes the path tracer brighter
    // than direct lighting alone, but never above the geometric series
    // a + a² + ... = a/(1 − a) of a closed furnace.
    nlohmann::json j = base_scene("path", 64);
    j["camera"] = {{"eye", {0, 0.5, 0}}, {"target", {0, 0, 0}}, {"up", {0, 0, -1}}, {"fov_deg", 5}};
    j["film"] = {{"width", 8}, {"height", 8}};
    j["materials"] = {{{"name", "m"}, {"type", "diffuse"}, {"albedo", 0.5}}};
    j["shapes"] = {{{"type", "quad"}, {"size", {4, 4}}, {"material", "m"}},
                   {{"type", "quad"},
                    {"size", {4, 4}},
                    {"material", "m"},
                    {"transform",
                     {{"rotate", {{"axis", {1, 0, 0}}, {"deg", 180}}}, {"translate", {0, 1, 0}}}}}};
    j["lights"] = {{{"type", "environment"}, {"radiance", 1.0}}};
    const Scene path_scene = parse_scene(j, "t.json");
    j["render"]["integrator"] = "direct";
    const Scene direct_scene = parse_scene(j, "t.json");
    const Stats p = box_stats(render_scene(path_scene, {0, true}), 0);
    const Stats d = box_stats(render_scene(direct_scene, {0, true}), 0);
    EXPECT_GT(p.mean, d.mean + 5.0 * (p.stderr_mean + d.stderr_mean));
    EXPECT_LT(p.mean, 0.5 / (1.0 - 0.5) + 5.0 * p.stderr_mean);
}

// A glossy point lit by a sphere light sees the same radiance, from the same
// cone of directions, as under a directional cone light with the light's
// solid angle at that point, its direction and its radiance (irradiance
// L π sin²θmax, docs/SCENE_FORMAT.md). The two lights take different code
// paths (finite-distance shadow rays and emitter hits vs escaped rays), so
// their agreement checks the sphere light's sampling, shadow rays and MIS.
// The camera looks at one surface point (fov 0.01°); limit 5σ of the MC
// noise plus 0.5% for the pixel footprint's spread of points.
TEST_P(Analytic, GlossyPointUnderSphereLightEqualsTheEquivalentCone) {
    const glm::vec3 p = glm::normalize(glm::vec3(-0.32f, 0.42f, 0.85f));
    const glm::vec3 center(-2.0f, 1.5f, 1.5f);
    const float radius = 0.4f, radiance = 4.0f;
    const float d = glm::length(center - p);
    const float sin2 = radius * radius / (d * d);
    const float solid_angle = glm::two_pi<float>() * (1.0f - std::sqrt(1.0f - sin2));
    const glm::vec3 axis = (center - p) / d;
    for (const float roughness : {0.2f, 0.5f}) {
        SCOPED_TRACE(roughness);
        nlohmann::json j = base_scene(GetParam(), 1024);
        j["film"] = {{"width", 4}, {"height", 4}};
        j["camera"] = {{"eye", {0, 0, 3.2}}, {"target", {p.x, p.y, p.z}}, {"fov_deg", 0.01}};
        j["materials"] = {{{"name", "m"},
                           {"type", "glint"},
                           {"model", "smooth"},
                           {"ndf", "ggx"},
                           {"roughness", roughness},
                           {"fresnel", {{"type", "conductor"}, {"metal", "silver"}}}}};
        j["shapes"] = {{{"type", "sphere"}, {"radius", 1.0}, {"material", "m"}}};
        j["lights"] = {{{"type", "sphere"},
                        {"center", {center.x, center.y, center.z}},
                        {"radius", radius},
                        {"radiance", radiance}}};
        const Stats sphere = box_stats(render_scene(parse_scene(j, "t.json"), {0, true}), 0);
        j["lights"] = {{{"type", "directional"},
                        {"direction", {axis.x, axis.y, axis.z}},
                        {"irradiance", radiance * glm::pi<float>() * sin2},
                        {"solid_angle_sr", solid_angle}}};
        const Stats cone = box_stats(render_scene(parse_scene(j, "t.json"), {0, true}), 0);
        ASSERT_GT(cone.mean, 0.05);
        EXPECT_NEAR(sphere.mean, cone.mean,
                    5.0 * (sphere.stderr_mean + cone.stderr_mean) + 0.005 * cone.mean)
            << "sphere light " << sphere.mean << ", cone " << cone.mean;
    }
}

TEST(Renderer, SameSeedIsBitIdenticalForAnyThreadCount) {
    nlohmann::json j = base_scene("path", 4);
    j["film"] = {{"width", 48}, {"height", 40}};
    j["camera"] = {{"eye", {0, 1, 5}}, {"target", {0, 0, 0}}, {"fov_deg", 40}};
    j["materials"] = {{{"name", "d"}, {"type", "diffuse"}, {"albedo", 0.5}},
                      {{"name", "g"}, {"type", "glint"}, {"model", "smooth"}, {"roughness", 0.2}}};
    j["shapes"] = {{{"type", "quad"}, {"size", {6, 6}}, {"material", "d"}},
                   {{"type", "sphere"}, {"center", {0, 1, 0}}, {"radius", 0.8}, {"material", "g"}}};
    j["lights"] = {{{"type", "environment"}, {"radiance", {0.3, 0.4, 0.5}}},
                   {{"type", "directional"},
                    {"direction", {1, 2, 1}},
                    {"irradiance", 3},
                    {"solid_angle_sr", 6.8e-5}}};
    const Scene scene = parse_scene(j, "t.json");
    const Image a = render_scene(scene, {1, true});
    const Image b = render_scene(scene, {2, true});
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_EQ(0,
              std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)));
    j["render"]["seed"] = 8;
    const Image c = render_scene(parse_scene(j, "t.json"), {2, true});
    EXPECT_NE(0,
              std::memcmp(a.pixels.data(), c.pixels.data(), a.pixels.size() * sizeof(glm::vec3)));
}

}  // namespace
}  // namespace glintlab
