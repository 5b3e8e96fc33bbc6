// deliot2023's GPU option "stochastic_grid" (issue 17): one of the 4 grids
// per pixel and frame, chosen by its weight; over frames its image has the
// mean of the default 4-grid blend.
#include <gtest/gtest.h>

#include <string>

#include "glintlab/bench/table1.h"
#include "glintlab/core/image.h"
#include "glintlab/realtime/gpu_renderer.h"
#include "glintlab/realtime/gpu_test_util.h"
#include "glintlab/scene/scene_loader.h"

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

}  // namespace
}  // namespace glintlab
