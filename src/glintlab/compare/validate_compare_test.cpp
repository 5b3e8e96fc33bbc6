#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "glintlab/compare/validate_compare.h"
#include "glintlab/core/error.h"
#include "glintlab/loader/scene_loader.h"

namespace glintlab {
namespace {

// The reduced `validate compare` run of ctest, a subset for CI time
// (docs/VALIDATION.md "compare", measured table):
// kneiphof2025 and smooth on the dense sphere under 'city' and the dense
// plane under 'forest'. Renders are deterministic (fixed seeds, per-pixel
// sample streams), so the values are those of the table, not a random draw.
// Realizations per scene: as many as the dense bound needs to be conclusive
// (standard error <= 2.5 %, check mean_rel_err_dense_se_max): city's sun
// makes its image mean a rare-event estimate (kneiphof2025 se 4.3 % with 3
// realizations, where it measured +5.4 %; 1.9 % with 12: +0.7 %; +0.4 % +-
// 1.5 % with 32), forest's se is 0.6 % with 3.
// Under the sanitizers (GLINTLAB_SANITIZED, ~5x slower) only the plane, the
// cheaper run of the same contract (the sphere's 12 realizations took 168 s
// of a 2-core sanitizer run).
// The other scenes and models are run by `glintlab validate compare` (~16 min
// on 2 cores; every check passes since the eleventh run, docs/VALIDATION.md).
TEST(CompareValidation, ReducedSuitePassesWithTheContractChecks) {
    const bool sanitized = std::getenv("GLINTLAB_SANITIZED") != nullptr;
    std::vector<std::pair<std::string, int>> runs = {{"plane25_forest", 3}};
    if (!sanitized) runs.emplace_back("sphere_city", 12);
    for (const auto& [scene, realizations] : runs) {
        SCOPED_TRACE(scene);
        CompareValidationOptions o;
        o.size = 48;
        o.realizations = realizations;
        // The truth: at least 8 realizations (dense scenes, its mean is not
        // heavy-tailed here), as many as the model's where those are needed.
        o.truth_realizations = std::max(8, realizations);
        o.frames = 3;
        o.spp = 8;
        o.scenes = {scene};
        o.models = {"smooth", "kneiphof2025"};
        o.max_flicker_paths = 0;  // CI time; FlickerNearABoundIsRemeasuredWithMorePaths
        const ValidationReport r = validate_compare(o);
        EXPECT_EQ(r.suite, "compare");
        std::set<std::string> names;
        for (const ValidationCheck& c : r.checks) {
            names.insert(c.name);
            EXPECT_TRUE(c.pass) << c.name << " = " << c.value << " " << c.relation << " "
                                << c.limit;
        }
        for (const char* name : {"mean_rel_err_max", "mean_rel_err_dense_se_max", "nan_count",
                                 "negative_count", "flicker_ratio_max", "flicker_ratio_min"})
            EXPECT_EQ(names.count(name), 1u) << name;
        const nlohmann::json j = r.to_json();
        ASSERT_EQ(j["scenes"].size(), 1u);
        for (const nlohmann::json& s : j["scenes"]) {
            EXPECT_EQ(s["density"], "dense");
            // explicit (one truth per fitted NDF), smooth, kneiphof2025.
            EXPECT_GE(s["models"].size(), 3u);
        }
        EXPECT_TRUE(r.passed());
    }
}

// The se a dense verdict needs: 2.5 % where the error is at least two se
// from the 5 % bound, else half the distance to it, never below 1.5 %.
TEST(CompareValidation, DenseSeTargetTightensNearTheBound) {
    EXPECT_DOUBLE_EQ(dense_mean_se_target(0.0, 0.02), 0.025);         // 2.5 se from the bound
    EXPECT_DOUBLE_EQ(dense_mean_se_target(-0.12, 0.02), 0.025);       // 3.5 se beyond it
    EXPECT_NEAR(dense_mean_se_target(0.0806, 0.023), 0.0153, 1e-12);  // the 7th run's sunrise
    EXPECT_NEAR(dense_mean_se_target(-0.01, 0.023), 0.02, 1e-12);     // |err| counts
    EXPECT_DOUBLE_EQ(dense_mean_se_target(0.049, 0.02), 0.015);       // the floor
    EXPECT_DOUBLE_EQ(dense_mean_se_target(0.05, 0.0), 0.025);         // no se: nothing to refine
}

// A dense scene's bounded model whose se is above 2.5 % is re-run with more
// seeds (R (se_m / b_m)² · 1.2, capped): kneiphof2025 on sphere_city has se
// ≈ 5 % from 2 seeds, so it is re-run, here with the cap of 4 (in up to 3
// rounds; at the cap it stops). Where the truth's part of the se is above
// 2.5 % / sqrt(2) the truth is re-run too (here with its cap of 6), and
// with it every model compared with it.
TEST(CompareValidation, DenseModelsWithALargeSeAreRerunWithMoreRealizations) {
    if (std::getenv("GLINTLAB_SANITIZED") != nullptr) GTEST_SKIP() << "the reduced suite covers it";
    CompareValidationOptions o;
    o.size = 32;
    o.realizations = 2;
    o.max_realizations = 4;
    o.truth_realizations = 4;
    o.max_truth_realizations = 4;  // never
    o.frames = 2;
    o.flicker_paths = 1;  // the refinement of the mean is the point here
    o.spp = 4;
    o.scenes = {"sphere_city"};
    o.models = {"kneiphof2025"};
    const nlohmann::json j = validate_compare(o).to_json();
    ASSERT_EQ(j["scenes"].size(), 1u);
    const nlohmann::json& s = j["scenes"][0];
    ASSERT_TRUE(s.contains("refined_realizations")) << s.dump();
    EXPECT_EQ(s["refined_realizations"]["kneiphof2025"], 4);
    o.max_realizations = 0;  // never
    EXPECT_FALSE(validate_compare(o).to_json()["scenes"][0].contains("refined_realizations"));
    o.truth_realizations = 2;
    o.max_truth_realizations = 6;
    const nlohmann::json t = validate_compare(o).to_json()["scenes"][0];
    ASSERT_TRUE(t.contains("refined_realizations")) << t.dump();
    const nlohmann::json& refined = t["refined_realizations"];
    // The truth, with its cap; the model was re-run with it, with the 2
    // realizations it had (refined_realizations lists only what grew).
    ASSERT_EQ(refined.size(), 1u) << refined.dump();
    for (const auto& [key, n] : refined.items()) {
        EXPECT_EQ(key.rfind("explicit", 0), 0u) << key;
        EXPECT_EQ(n, 6) << key;
    }
    for (const nlohmann::json& m : t["models"]) {
        if (m["compared"].get<bool>() && m["model"] == "explicit") {
            EXPECT_GT(m["mean_luminance_rel_se"].get<double>(), 0.0);
        }
    }
}

// A flicker ratio within flicker_refine_se standard errors of a bound is
// re-measured over max_flicker_paths paths: with a margin no ratio escapes
// (1e9 se) the model is re-run and its flicker now has that many paths'
// standard error (smaller than 2 paths' on average; here only its presence
// and the listing are asserted, the values being draws); with margin 0 or
// max_flicker_paths <= flicker_paths nothing is.
TEST(CompareValidation, FlickerNearABoundIsRemeasuredWithMorePaths) {
    if (std::getenv("GLINTLAB_SANITIZED") != nullptr) GTEST_SKIP() << "CI time; no new code paths";
    CompareValidationOptions o;
    o.size = 24;
    o.realizations = 2;
    o.max_realizations = 0;  // the mean's refinement is not the point here
    o.truth_realizations = 2;
    o.max_truth_realizations = 0;
    o.frames = 2;
    o.flicker_paths = 2;
    o.max_flicker_paths = 4;
    o.flicker_refine_se = 1e9;
    o.spp = 2;
    o.scenes = {"lights_point_directional"};
    o.models = {"smooth", "deliot2023"};
    const nlohmann::json s = validate_compare(o).to_json()["scenes"][0];
    ASSERT_TRUE(s.contains("refined_flicker_paths")) << s.dump();
    // deliot2023 is real-time (flicker-bounded); smooth has no sparkle.
    EXPECT_EQ(s["refined_flicker_paths"].size(), 1u) << s["refined_flicker_paths"].dump();
    EXPECT_EQ(s["refined_flicker_paths"]["deliot2023"], 4);
    o.flicker_refine_se = 0.0;
    EXPECT_FALSE(validate_compare(o).to_json()["scenes"][0].contains("refined_flicker_paths"));
    o.flicker_refine_se = 1e9;
    o.max_flicker_paths = 2;
    EXPECT_FALSE(validate_compare(o).to_json()["scenes"][0].contains("refined_flicker_paths"));
    o.max_flicker_paths = 257;
    EXPECT_THROW(validate_compare(o), Error);
    o.max_flicker_paths = 4;
    o.flicker_refine_se = std::nan("");
    EXPECT_THROW(validate_compare(o), Error);
}

TEST(CompareValidation, RejectsUnknownScenesAndSizes) {
    CompareValidationOptions o;
    o.scenes = {"no_such_scene"};
    EXPECT_THROW(validate_compare(o), Error);
    o.scenes = {"sphere_city"};
    o.size = 4;
    EXPECT_THROW(validate_compare(o), Error);
    EXPECT_EQ(compare_scene_names().size(), 13u);
}

}  // namespace
}  // namespace glintlab

namespace glintlab {
namespace {

// Every compare scene loads (strictly, with its HDRI and mesh), and together
// they use every Blender HDRI, a sphere, a quad, a glTF mesh and scenes
// without an environment (docs/VALIDATION.md "compare", "Scenes").
TEST(CompareValidation, SceneListCoversEveryHdriAndShape) {
    const std::filesystem::path dir =
        std::filesystem::path(GLINTLAB_SOURCE_DIR) / "scenes" / "compare";
    std::set<std::string> hdris, shapes;
    int without_environment = 0;
    for (const std::string& name : compare_scene_names()) {
        std::ifstream in(dir / (name + ".json"));
        ASSERT_TRUE(in) << name;
        const nlohmann::json doc = nlohmann::json::parse(in);
        for (const nlohmann::json& s : doc["shapes"]) shapes.insert(s["type"].get<std::string>());
        bool env = false;
        for (const nlohmann::json& l : doc["lights"])
            if (l["type"] == "environment") {
                env = true;
                hdris.insert(std::filesystem::path(l["file"].get<std::string>()).stem());
            }
        without_environment += !env;
        const Scene scene = load_scene(dir / (name + ".json"));  // strict: throws on any error
        EXPECT_EQ(scene.materials.at(0).type, MaterialDesc::Type::Glint) << name;
    }
    EXPECT_EQ(hdris, (std::set<std::string>{"city", "courtyard", "forest", "interior", "night",
                                            "studio", "sunrise", "sunset"}));
    for (const char* shape : {"sphere", "quad", "gltf"})
        EXPECT_EQ(shapes.count(shape), 1u) << shape;
    EXPECT_GE(without_environment, 2);
}

// A density map is classed by its sparsest texel: the compare textures' bar
// of ln N 9 makes both textured scenes sparse, whatever their mean.
TEST(CompareValidation, TexturedScenesAreClassedByTheirSparsestTexel) {
    const std::filesystem::path dir =
        std::filesystem::path(GLINTLAB_SOURCE_DIR) / "scenes" / "compare";
    for (const char* name : {"textured_lights", "textured_sphere_forest"})
        EXPECT_NEAR(compare_scene_log_density(load_scene(dir / (std::string(name) + ".json"))),
                    9.0f, 1e-3f)
            << name;
    EXPECT_NEAR(compare_scene_log_density(load_scene(dir / "lights_point_directional.json")), 12.0f,
                1e-6f);
}

}  // namespace
}  // namespace glintlab
