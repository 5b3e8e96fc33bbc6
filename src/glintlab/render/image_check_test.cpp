#include "glintlab/render/image_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/loader/scene_loader.h"

namespace glintlab {
namespace {

Scene sphere_scene() {
    const nlohmann::json doc = nlohmann::json::parse(R"({
      "film": {"width": 16, "height": 16},
      "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "fov_deg": 40},
      "materials": [{"name": "glitter", "type": "glint", "model": "deliot2023", "roughness": 0.3}],
      "shapes": [{"name": "ball", "type": "sphere", "radius": 1.0, "material": "glitter"}],
      "lights": [{"type": "point", "position": [1, 3, 2]}]
    })");
    return parse_scene(doc, "check.json");
}

TEST(ImageCheck, FiniteImagePasses) {
    const Scene scene = sphere_scene();
    Image image(16, 16);
    EXPECT_FALSE(find_non_finite_pixel(image).has_value());
    EXPECT_NO_THROW(require_finite_image(scene, image, "render of check.json"));
}

// The error names the first bad pixel (row-major), how many there are, and
// the material and model the camera sees there; a pixel off the sphere says so.
TEST(ImageCheck, NonFinitePixelNamesPixelMaterialAndModel) {
    const Scene scene = sphere_scene();
    Image image(16, 16);
    image.at(8, 8) = glm::vec3(0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f);
    image.at(9, 9).x = std::numeric_limits<float>::infinity();
    const auto bad = find_non_finite_pixel(image);
    ASSERT_TRUE(bad.has_value());
    EXPECT_EQ(bad->x, 8);
    EXPECT_EQ(bad->y, 8);
    try {
        require_finite_image(scene, image, "render of check.json");
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("render of check.json"), std::string::npos) << m;
        EXPECT_NE(m.find("2 pixel(s)"), std::string::npos) << m;
        EXPECT_NE(m.find("pixel (8, 8)"), std::string::npos) << m;
        EXPECT_NE(m.find("'glitter'"), std::string::npos) << m;
        EXPECT_NE(m.find("deliot2023"), std::string::npos) << m;
    }
    EXPECT_NE(describe_pixel_surface(scene, 0, 0).find("no surface"), std::string::npos);
}

}  // namespace
}  // namespace glintlab
