// Scene integration of wang2020: the parameter block is read strictly and the
// material constraints name the key and range.
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/glints/model_params.h"
#include "glintlab/glints/registry.h"
#include "glintlab/scene/scene_loader.h"

namespace glintlab {
namespace {

nlohmann::json scene_with(const nlohmann::json& material) {
    return {{"film", {{"width", 8}, {"height", 8}}},
            {"camera", {{"eye", {0, 0, 3}}, {"target", {0, 0, 0}}, {"fov_deg", 45}}},
            {"materials", {material}},
            {"shapes", {{{"name", "s"}, {"type", "sphere"}, {"radius", 1.0}, {"material", "g"}}}},
            {"lights", {{{"type", "point"}, {"position", {1, 1, 2}}, {"intensity", 1.0}}}}};
}

nlohmann::json glint_material(nlohmann::json block) {
    return {
        {"name", "g"},      {"type", "glint"},   {"model", "wang2020"},         {"ndf", "beckmann"},
        {"roughness", 0.4}, {"log_density", 12}, {"wang2020", std::move(block)}};
}

std::string error_of(const nlohmann::json& doc) {
    try {
        parse_scene(doc, "test.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(Wang2020Model, ReadsItsBlockAndRejectsBadInput) {
    const Scene ok =
        parse_scene(scene_with(glint_material({{"gamma_deg", 3}, {"depth", 9}})), "test.json");
    const auto& p = std::get<Wang2020Params>(ok.materials[0].glint.params);
    EXPECT_DOUBLE_EQ(p.gamma_deg, 3.0);
    EXPECT_EQ(p.depth, 9);
    EXPECT_EQ(p.dpf_theta, 90);  // Table 2 default
    ASSERT_NE(find_glint_model("wang2020"), nullptr);
    EXPECT_FALSE(find_glint_model("wang2020")->sphere_lights);

    EXPECT_NE(error_of(scene_with(glint_material({{"gamma_deg", 0.5}}))).find("gamma_deg"),
              std::string::npos);
    EXPECT_NE(error_of(scene_with(glint_material({{"depth", 20}}))).find("depth"),
              std::string::npos);
    EXPECT_NE(error_of(scene_with(glint_material({{"unknown_key", 1}}))).find("unknown_key"),
              std::string::npos);
    nlohmann::json ggx = glint_material(nlohmann::json::object());
    ggx["ndf"] = "ggx";
    EXPECT_NE(error_of(scene_with(ggx)).find("Beckmann"), std::string::npos);
    nlohmann::json dense = glint_material(nlohmann::json::object());
    dense["log_density"] = 25;
    EXPECT_NE(error_of(scene_with(dense)).find("log_density"), std::string::npos);
}

}  // namespace
}  // namespace glintlab
