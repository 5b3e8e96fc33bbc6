#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "glintlab/compare/compare.h"

namespace glintlab {
namespace {

// scenes/compare/lights_point_directional.json at 16 x 16 (a plane and a
// sphere under a point and a directional light), its material of `model`
// and, when `block` is not null, that model's parameter block.
std::filesystem::path write_scene(const std::string& name, const std::string& model,
                                  const nlohmann::json& block) {
    nlohmann::json material = {{"name", "glitter"},
                               {"type", "glint"},
                               {"model", model},
                               {"ndf", "beckmann"},
                               {"roughness", 0.3},
                               {"log_density", 12},
                               {"fresnel", {{"type", "conductor"}, {"metal", "silver"}}}};
    if (!block.is_null()) material[model] = block;
    const nlohmann::json scene = {
        {"film", {{"width", 16}, {"height", 16}}},
        {"camera", {{"eye", {0.0, 1.268, 2.719}}, {"target", {0, 0, 0}}, {"fov_deg", 45}}},
        {"render", {{"integrator", "direct"}, {"spp", 1}, {"seed", 1}}},
        {"materials", {material}},
        {"shapes",
         {{{"type", "quad"}, {"size", {2, 2}}, {"material", "glitter"}},
          {{"type", "sphere"}, {"center", {0, 0.5, 0}}, {"radius", 0.5}, {"material", "glitter"}}}},
        {"lights",
         {{{"type", "point"}, {"position", {1.5, 2.5, 1.0}}, {"intensity", 6.0}},
          {{"type", "directional"}, {"direction", {-0.4, 0.6, -0.7}}, {"irradiance", 1.5}}}}};
    const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
    std::ofstream(path) << scene.dump(1);
    return path;
}

compare::ModelMetrics deliot2023_row(const std::filesystem::path& scene) {
    compare::CompareOptions o;
    o.scene = scene;
    o.models = {"deliot2023"};
    o.realizations = 2, o.frames = 2, o.threads = 1;
    const compare::CompareResult r = compare::run_compare(o);
    const compare::ModelMetrics* row = r.find("deliot2023");
    EXPECT_NE(row, nullptr);
    return row != nullptr ? *row : compare::ModelMetrics{};
}

// The scene's own model is rendered with the scene's parameters, not its
// defaults: deliot2023 with the default microfacet_roughness given
// explicitly renders the same images as without the block, and with the
// roughness of explicit's 1-degree cone (D(n) pi gamma^2 / 4 = 8.5e-4 for
// Beckmann 0.3) different ones (fewer, brighter sparkles).
TEST(Compare, TheScenesOwnModelKeepsTheScenesParameters) {
    const auto plain = deliot2023_row(write_scene("compare_own_plain.json", "deliot2023", nullptr));
    const auto given = deliot2023_row(
        write_scene("compare_own_given.json", "deliot2023", {{"microfacet_roughness", 0.025}}));
    const auto narrow = deliot2023_row(
        write_scene("compare_own_narrow.json", "deliot2023", {{"microfacet_roughness", 0.00085}}));
    EXPECT_EQ(plain.mean_luminance, given.mean_luminance);
    EXPECT_EQ(plain.pixel_variance, given.pixel_variance);
    // Per-pixel variance over realizations grows as the same mean is carried
    // by rarer facets: p per facet falls 29x.
    EXPECT_GT(narrow.pixel_variance, 2.0 * plain.pixel_variance)
        << narrow.mean_luminance << " " << plain.mean_luminance;
}

}  // namespace
}  // namespace glintlab
