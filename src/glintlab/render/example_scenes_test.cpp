// Every example scene in scenes/ loads and renders (at a tiny resolution), so
// the shipped examples cannot rot as the format and models evolve.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/renderer.h"

namespace glintlab {
namespace {

TEST(ExampleScenes, AllLoadAndRenderFiniteNonBlackImages) {
    const std::filesystem::path dir = std::filesystem::path(GLINTLAB_SOURCE_DIR) / "scenes";
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        ++count;
        Scene scene = load_scene(entry.path());
        scene.camera.width = 24;
        scene.camera.height = 16;
        scene.render.spp = 1;
        const Image image = render_scene(scene, RenderOptions{1, true});
        double sum = 0.0;
        for (const glm::vec3& p : image.pixels) {
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
                << entry.path();
            ASSERT_GE(std::min({p.x, p.y, p.z}), 0.0f) << entry.path();
            sum += p.x + p.y + p.z;
        }
        EXPECT_GT(sum, 0.0) << entry.path() << " renders black";
    }
    EXPECT_GE(count, 7);
}

}  // namespace
}  // namespace glintlab
