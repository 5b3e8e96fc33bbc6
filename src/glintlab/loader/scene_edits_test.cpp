// Scene edits (render --model / --set): values land where the pointer says,
// the strict loader still checks them, and every error names the pointer.
#include "glintlab/loader/scene_edits.h"

#include <gtest/gtest.h>

#include <fstream>

#include "glintlab/core/error.h"
#include "glintlab/core/image_test_util.h"

namespace glintlab {
namespace {

nlohmann::json doc() {
    return nlohmann::json::parse(R"({
      "camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
      "materials": [{"name": "d", "type": "diffuse"},
                    {"name": "g", "type": "glint", "model": "smooth", "roughness": 0.3}],
      "shapes": [{"type": "sphere", "material": "g"}],
      "lights": [{"type": "point", "position": [0, 2, 2], "intensity": 5}]
    })");
}

std::string error_of(auto&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(SceneEdits, OverridesSetNestedValuesArraysAndBareStrings) {
    nlohmann::json d = doc();
    apply_override_assignment(d, "/materials/1/log_density=14.5");
    EXPECT_EQ(d["materials"][1]["log_density"], 14.5);
    apply_override_assignment(d, "/materials/1/ndf=ggx");  // bare word → string
    EXPECT_EQ(d["materials"][1]["ndf"], "ggx");
    apply_override_assignment(d, "/camera/eye/2=7");
    EXPECT_EQ(d["camera"]["eye"][2], 7);
    apply_override_assignment(d, R"(/lights/-={"type": "point", "position": [1, 1, 1]})");
    EXPECT_EQ(d["lights"].size(), 2u);
    apply_override_assignment(d, "/materials/1/fresnel={\"type\": \"none\"}");
    EXPECT_EQ(d["materials"][1]["fresnel"]["type"], "none");
}

TEST(SceneEdits, ErrorsNameThePointer) {
    nlohmann::json d = doc();
    const std::string missing =
        error_of([&] { apply_override_assignment(d, "/materials/1/nope/x=1"); });
    EXPECT_NE(missing.find("/materials/1/nope/x"), std::string::npos) << missing;
    EXPECT_NE(missing.find("/materials/1/nope does not exist"), std::string::npos) << missing;
    const std::string index = error_of([&] { apply_override_assignment(d, "/materials/5/a=1"); });
    EXPECT_NE(index.find("does not exist"), std::string::npos) << index;
    const std::string beyond = error_of([&] { apply_override_assignment(d, "/camera/eye/3=1"); });
    EXPECT_NE(beyond.find("has 3 entries, no index 3"), std::string::npos) << beyond;
    const std::string leading = error_of([&] { apply_override_assignment(d, "/camera/eye/01=1"); });
    EXPECT_NE(leading.find("is not an index"), std::string::npos) << leading;
    const std::string scalar =
        error_of([&] { apply_override_assignment(d, "/materials/1/roughness/x=1"); });
    EXPECT_NE(scalar.find("neither an object nor an array"), std::string::npos) << scalar;
    const std::string syntax = error_of([&] { apply_override_assignment(d, "materials=1"); });
    EXPECT_NE(syntax.find("not a JSON pointer"), std::string::npos) << syntax;
    const std::string no_eq = error_of([&] { apply_override_assignment(d, "/film"); });
    EXPECT_NE(no_eq.find("POINTER=VALUE"), std::string::npos) << no_eq;
    EXPECT_NE(error_of([&] { apply_override(d, "", 1); }), "");
}

TEST(SceneEdits, ModelSwitchesGlintMaterialsOnlyAndTheLoaderStillChecks) {
    nlohmann::json d = doc();
    set_glint_model(d, "deliot2023");
    EXPECT_EQ(d["materials"][1]["model"], "deliot2023");
    EXPECT_FALSE(d["materials"][0].contains("model"));
    nlohmann::json no_glint = doc();
    no_glint["materials"].erase(1);
    EXPECT_NE(error_of([&] { set_glint_model(no_glint, "smooth"); }).find("no glint material"),
              std::string::npos);

    testing::ScratchDir dir;
    const auto file = dir / "s.json";
    std::ofstream(file) << doc().dump();
    // An edit is checked like the file: out of range names file and path.
    const std::string range = error_of([&] {
        load_scene(file, SceneEdits{"", {"/materials/1/roughness=7"}});
    });
    EXPECT_NE(range.find("s.json"), std::string::npos) << range;
    EXPECT_NE(range.find("/materials/1/roughness"), std::string::npos) << range;
    const std::string unknown = error_of([&] { load_scene(file, SceneEdits{"nosuchmodel", {}}); });
    EXPECT_NE(unknown.find("nosuchmodel"), std::string::npos) << unknown;
    const Scene s = load_scene(file, SceneEdits{"zirr2016", {"/materials/1/log_density=12"}});
    EXPECT_EQ(s.materials[1].glint.model_id, GlintModelId::Zirr2016);
    EXPECT_FLOAT_EQ(s.materials[1].glint.log_density, 12.0f);
}

// `render --model kneiphof2025` failed on most scenes: glint materials
// default to Beckmann and kneiphof2025 needs GGX. The switch fits what the
// model requires, as the viewer's does, and says what it changed.
TEST(SceneEdits, ModelSwitchGivesAMaterialTheModelAccepts) {
    testing::ScratchDir dir;
    const auto file = dir / "s.json";
    nlohmann::json d = doc();
    d["materials"][1]["base_albedo"] = 0.3;
    d["materials"][1]["fresnel"] = {{"type", "dielectric"}, {"eta", 1.5}};
    d["materials"][1]["log_density"] = 25;
    std::ofstream(file) << d.dump();
    ::testing::internal::CaptureStderr();
    const Scene k = load_scene(file, SceneEdits{"kneiphof2025", {}});
    const std::string notes = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(k.materials[1].glint.ndf, NdfType::GGX);
    EXPECT_FALSE(k.materials[1].glint.has_base());
    EXPECT_NE(notes.find("/materials/1/ndf: \"beckmann\" -> \"ggx\""), std::string::npos) << notes;
    EXPECT_NE(notes.find("/materials/1/base_albedo removed"), std::string::npos) << notes;
    ::testing::internal::CaptureStderr();
    const Scene w = load_scene(file, SceneEdits{"wang2020", {}});
    (void)::testing::internal::GetCapturedStderr();
    EXPECT_FLOAT_EQ(w.materials[1].glint.log_density, 19.4f);
    // A later --set still wins over the fit (and the loader judges it).
    EXPECT_NE(error_of([&] {
                  load_scene(file, SceneEdits{"kneiphof2025", {"/materials/1/ndf=beckmann"}});
              }).find("/materials/1"),
              std::string::npos);
}

}  // namespace
}  // namespace glintlab
