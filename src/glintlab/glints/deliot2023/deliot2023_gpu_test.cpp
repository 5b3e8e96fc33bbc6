// deliot2023's GPU option "stochastic_grid": one of the 4 grids per pixel
// and frame, chosen by its weight; over frames its image has the mean of the
// default 4-grid blend. And the GPU glues' per-footprint cache
// of D_P's half-vector-free part (deliot2023.glsl
// deliot2023_cached_pixel_part): several lights shade as each alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "glintlab/bench/table1.h"
#include "glintlab/core/image.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/realtime/gpu_renderer.h"
#include "glintlab/realtime/gpu_test_util.h"

namespace glintlab {
namespace {

double mean_luminance(const Image& img) {
    double sum = 0.0;
    for (const glm::vec3& c : img.pixels) sum += luminance(c);
    return sum / double(img.pixels.size());
}

// PLANE_90 of bench/table1 (the plane fills the view), 96 x 96, ln N = 14.
// The image mean of the default blend against the mean over 8 stochastic
// frames: both estimate the same expectation with the same per-vertex laws,
// measured 0.2 % apart (0.7867 vs 0.7883); a first version that gave the
// chosen grid all the footprint's trials was 4.2 % low (the gated law's
// small-N bias then differs), which the 2 % limit catches. Consecutive
// frames draw new grids (the images differ), and the option also compiles
// and renders with the noise texture (its own uniforms: within 20 %).
TEST(GpuDeliot2023Stochastic, FramesAverageToTheBlendMean) {
    GLINTLAB_REQUIRE_GL();
    const Scene scene =
        parse_scene(table1_scene_json("PLANE_90", "deliot2023", 14.0f, 96, 96), "test:plane90");
    GpuRenderer renderer(scene);
    renderer.render(scene);
    const double blend = mean_luminance(renderer.read_image());
    renderer.set_model_option("deliot2023", "stochastic_grid", true);
    double sum = 0.0;
    Image first;
    bool frames_differ = false;
    const int frames = 8;
    for (int f = 0; f < frames; ++f) {
        renderer.render(scene);
        const Image img = renderer.read_image();
        sum += mean_luminance(img);
        if (f == 0)
            first = img;
        else
            frames_differ = frames_differ || img.pixels != first.pixels;
    }
    const double stochastic = sum / frames;
    RecordProperty("blend_mean", std::to_string(blend));
    RecordProperty("stochastic_mean", std::to_string(stochastic));
    ASSERT_GT(blend, 1e-3);
    EXPECT_NEAR(stochastic / blend, 1.0, 0.02);
    EXPECT_TRUE(frames_differ);
    renderer.set_model_option("deliot2023", "noise_texture", true);
    renderer.render(scene);
    EXPECT_NEAR(mean_luminance(renderer.read_image()) / blend, 1.0, 0.2);
}

// Under several lights the forward pass builds the half-vector-free part of
// D_P for the first light that needs the counts and reuses it for the rest;
// each light alone builds it itself. So the image under 4 lights must be the
// sum of the 4 single-light images up to the rounding of the sum (a few fp32
// ulps; 1e-5 relative), for deliot2023 and for kneiphof2025's point and
// directional lights (deliot2023's D_P). The lights differ in direction, so
// that some take the expectation exit where others need the counts (the
// lazy build after an exit is exercised); a stale or mis-built part would
// change the counts completely (a different glint pattern), far above 1e-5.
// No shadows on the plane (nothing occludes it), so visibility is 1.
TEST(GpuDeliot2023PixelCache, SeveralLightsShadeAsTheSumOfEachAlone) {
    GLINTLAB_REQUIRE_GL();
    const nlohmann::json lights = nlohmann::json::parse(R"([
        {"type": "directional", "direction": [0.0, 0.15, -1.0], "irradiance": 2.0},
        {"type": "directional", "direction": [0.3, 0.8, 0.5], "irradiance": 1.5},
        {"type": "point", "position": [0.5, 1.0, 0.3], "intensity": 3.0},
        {"type": "point", "position": [-0.6, 0.8, -0.4], "intensity": 2.0}])");
    for (const std::string model : {"deliot2023", "kneiphof2025"}) {
        nlohmann::json doc = table1_scene_json("PLANE_25", model, 14.0f, 64, 48);
        if (model == "kneiphof2025") doc["materials"][0]["ndf"] = "ggx";  // its tables are GGX
        doc["lights"] = lights;
        const Scene all = parse_scene(doc, "test:four_lights");
        GpuRenderer renderer(all);
        renderer.render(all);
        const Image together = renderer.read_image();
        std::vector<glm::vec3> sum(together.pixels.size(), glm::vec3(0.0f));
        for (const nlohmann::json& light : lights) {
            nlohmann::json one = doc;
            one["lights"] = nlohmann::json::array({light});
            const Scene scene = parse_scene(one, "test:one_light");
            GpuRenderer single(scene);
            single.render(scene);
            const Image img = single.read_image();
            ASSERT_EQ(img.pixels.size(), sum.size());
            for (size_t i = 0; i < sum.size(); ++i) sum[i] += img.pixels[i];
        }
        double worst = 0.0, total = 0.0;
        for (size_t i = 0; i < sum.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                const double a = together.pixels[i][c], b = sum[i][c];
                ASSERT_TRUE(std::isfinite(a)) << model << " pixel " << i;
                worst = std::max(worst, std::abs(a - b) / std::max(std::abs(b), 1e-3));
                total += b;
            }
        RecordProperty(model + "_worst_relative", std::to_string(worst));
        EXPECT_GT(total, 1.0) << model << ": the lights must light the plane";
        EXPECT_LT(worst, 1e-5) << model;
    }
}

}  // namespace
}  // namespace glintlab
