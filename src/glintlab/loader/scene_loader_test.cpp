// Strict scene parsing: each malformed scene gives an error that names the
// file, the JSON path and what is allowed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/memory_limit.h"
#include "glintlab/loader/scene_loader.h"

namespace glintlab {
namespace {

nlohmann::json valid_scene() {
    return nlohmann::json::parse(R"({
      "film": {"width": 16, "height": 8},
      "camera": {"eye": [0, 1, 4], "target": [0, 0, 0], "fov_deg": 40},
      "render": {"integrator": "direct", "spp": 2},
      "materials": [
        {"name": "floor", "type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
        {"name": "flakes", "type": "glint", "model": "smooth", "ndf": "ggx", "roughness": [0.2, 0.3],
         "fresnel": {"type": "conductor", "metal": "gold"}}
      ],
      "shapes": [
        {"type": "quad", "size": [4, 4], "material": "floor"},
        {"type": "sphere", "center": [0, 1, 0], "radius": 0.5, "material": "flakes"}
      ],
      "lights": [{"type": "point", "position": [0, 3, 0], "intensity": 10}]
    })");
}

std::string error_of(const nlohmann::json& j) {
    try {
        parse_scene(j, "bad.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "<no error>";
}

TEST(SceneLoader, ValidSceneParses) {
    const Scene s = parse_scene(valid_scene(), "ok.json");
    EXPECT_EQ(s.camera.width, 16);
    EXPECT_EQ(s.camera.height, 8);
    EXPECT_EQ(s.render.spp, 2);
    ASSERT_EQ(s.materials.size(), 2u);
    EXPECT_EQ(s.materials[1].glint.model_id, GlintModelId::Smooth);
    EXPECT_FLOAT_EQ(s.materials[1].glint.alpha_y, 0.3f);
    EXPECT_EQ(s.materials[1].glint.ndf, NdfType::GGX);
    ASSERT_EQ(s.shapes.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<SphereGeometry>(s.shapes[1].geometry));
    ASSERT_EQ(s.lights.size(), 1u);
}

struct BadCase {
    const char* what;
    std::function<void(nlohmann::json&)> edit;
    std::vector<std::string> expected;  // substrings of the message
};

TEST(SceneLoader, MalformedScenesGiveClearErrors) {
    const std::vector<BadCase> cases = {
        {"unknown top-level key",
         [](auto& j) { j["lightz"] = 1; },
         {"bad.json", "/lightz", "unknown key"}},
        {"unknown material key",
         [](auto& j) { j["materials"][0]["colour"] = 1; },
         {"/materials/0/colour", "unknown key", "albedo"}},
        // The glint material's list names ndf and the model blocks (it
        // omitted both), and a model block's lists its parameters (it was
        // empty).
        {"unknown glint material key",
         [](auto& j) { j["materials"][1]["colr"] = 1; },
         {"/materials/1/colr", "unknown key", "ndf", "deliot2023", "wang2020"}},
        {"unknown model block key",
         [](auto& j) {
             j["materials"][1]["smooth"] = {{"nope", 1}};
         },
         {"/materials/1/smooth/nope", "unknown key", "this object takes no keys"}},
        {"unknown deliot2023 key",
         [](auto& j) {
             j["materials"][1]["model"] = "deliot2023";
             j["materials"][1]["deliot2023"] = {{"nope", 1}};
         },
         {"/materials/1/deliot2023/nope", "microfacet_roughness", "screen_space_scale"}},
        {"albedo out of range",
         [](auto& j) {
             j["materials"][0]["albedo"] = {0.5, 1.5, 0.5};
         },
         {"/materials/0/albedo", "component 1", "[0, 1]"}},
        {"albedo wrong type",
         [](auto& j) { j["materials"][0]["albedo"] = "grey"; },
         {"/materials/0/albedo", "expected an RGB array"}},
        {"roughness out of range",
         [](auto& j) { j["materials"][1]["roughness"] = 3.0; },
         {"/materials/1/roughness", "out of range", "[0.001, 1]"}},
        {"unknown glint model",
         [](auto& j) { j["materials"][1]["model"] = "zirr2099"; },
         {"/materials/1/model", "unknown glint model \"zirr2099\"", "smooth"}},
        {"unknown ndf",
         [](auto& j) { j["materials"][1]["ndf"] = "phong"; },
         {"/materials/1/ndf", "phong", "beckmann, ggx"}},
        {"unknown curvature",
         [](auto& j) { j["materials"][1]["curvature"] = "lean"; },
         {"/materials/1/curvature", "lean", "none, footprint"}},
        {"unknown material type",
         [](auto& j) { j["materials"][0]["type"] = "velvet"; },
         {"/materials/0/type", "velvet", "diffuse"}},
        {"duplicate material",
         [](auto& j) { j["materials"][1]["name"] = "floor"; },
         {"/materials/1/name", "duplicate"}},
        {"unknown material reference",
         [](auto& j) { j["shapes"][0]["material"] = "nope"; },
         {"/shapes/0/material", "unknown material \"nope\""}},
        {"missing material",
         [](auto& j) { j["shapes"][0].erase("material"); },
         {"/shapes/0/material", "missing"}},
        {"negative radius",
         [](auto& j) { j["shapes"][1]["radius"] = -1; },
         {"/shapes/1/radius", "out of range"}},
        {"NaN-like value",
         [](auto& j) { j["camera"]["fov_deg"] = nullptr; },
         {"/camera/fov_deg", "expected a number", "[0.01, 179]"}},
        {"fov out of range",
         [](auto& j) { j["camera"]["fov_deg"] = 180; },
         {"/camera/fov_deg", "[0.01, 179]"}},
        {"eye equals target",
         [](auto& j) {
             j["camera"]["target"] = {0, 1, 4};
         },
         {"/camera/target", "must differ"}},
        {"zero width", [](auto& j) { j["film"]["width"] = 0; }, {"/film/width", "[1, 16384]"}},
        {"non-integer spp",
         [](auto& j) { j["render"]["spp"] = 1.5; },
         {"/render/spp", "expected an integer"}},
        {"unknown integrator",
         [](auto& j) { j["render"]["integrator"] = "bdpt"; },
         {"/render/integrator", "bdpt", "path, direct"}},
        {"missing obj file",
         [](auto& j) {
             j["shapes"][0] = {{"type", "obj"}, {"file", "missing.obj"}, {"material", "floor"}};
         },
         {"/shapes/0/file", "file not found", "missing.obj"}},
        {"missing environment file",
         [](auto& j) {
             j["lights"][0] = {{"type", "environment"}, {"file", "nope.exr"}};
         },
         {"/lights/0/file", "file not found"}},
        {"environment file is a directory",
         [](auto& j) {
             j["lights"][0] = {{"type", "environment"}, {"file", "/tmp"}};
         },
         {"/lights/0/file", "/tmp is a directory"}},
        {"environment file is a device",
         [](auto& j) {
             j["lights"][0] = {{"type", "environment"}, {"file", "/dev/zero"}};
         },
         {"/lights/0/file", "/dev/zero is a device, FIFO or socket, not a regular file"}},
        {"environment without source",
         [](auto& j) {
             j["lights"][0] = {{"type", "environment"}};
         },
         {"/lights/0/file", "exactly one"}},
        {"zero light direction",
         [](auto& j) {
             j["lights"][0] = {{"type", "directional"}, {"direction", {0, 0, 0}}};
         },
         {"/lights/0/direction", "non-zero"}},
        {"non-similarity sphere transform",
         [](auto& j) {
             j["shapes"][1]["transform"] = {{"scale", {1, 2, 1}}};
         },
         {"/shapes/1/transform", "uniform"}},
        {"camera missing", [](auto& j) { j.erase("camera"); }, {"/camera", "missing"}},
        {"materials not an array",
         [](auto& j) {
             j["materials"] = {{"a", 1}};
         },
         {"/materials", "expected an array"}},
        {"bloom strength out of range",
         [](auto& j) {
             j["film"]["bloom"] = {{"strength", 2}};
         },
         {"/film/bloom/strength", "[0, 1]"}},
        {"glint material on a mesh without uvs",
         [](auto& j) {
             // Write an OBJ without texture coordinates.
             const auto path = std::filesystem::temp_directory_path() / "glintlab_no_uv.obj";
             std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
             j["shapes"][0] = {{"type", "obj"}, {"file", path.string()}, {"material", "flakes"}};
         },
         {"/shapes/0/material", "needs a uv parameterization"}},
    };
    for (const BadCase& c : cases) {
        nlohmann::json j = valid_scene();
        c.edit(j);
        const std::string message = error_of(j);
        for (const std::string& expected : c.expected)
            EXPECT_NE(message.find(expected), std::string::npos)
                << c.what << ": expected \"" << expected << "\" in: " << message;
    }
}

TEST(SceneLoader, FileErrorsNameTheFile) {
    const auto dir = std::filesystem::temp_directory_path();
    try {
        load_scene(dir / "glintlab_does_not_exist.json");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("glintlab_does_not_exist.json"), std::string::npos);
    }
    const auto bad = dir / "glintlab_bad_syntax.json";
    std::ofstream(bad) << "{\"camera\": {\"eye\": [0, 1, }";
    try {
        load_scene(bad);
        FAIL();
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("glintlab_bad_syntax.json"), std::string::npos) << m;
        EXPECT_NE(m.find("invalid JSON"), std::string::npos) << m;
    }
}

TEST(SceneLoader, InactiveModelBlocksAreKeptForSwitching) {
    // Parameters of the active model are read; blocks of other known models
    // may stay in the file (switching the model is one word).
    nlohmann::json j = valid_scene();
    j["materials"][1]["smooth"] = nlohmann::json::object();
    EXPECT_NO_THROW(parse_scene(j, "ok.json"));
    j["materials"][1]["smooth"] = {{"bogus", 1}};
    EXPECT_NE(error_of(j).find("/materials/1/smooth/bogus"), std::string::npos) << error_of(j);
}

// Regression: the documented minimum roughness 0.001 of a glint material was
// rejected as "value 0.001 out of range: allowed in [0.001, 1]" (float bound).
TEST(SceneLoader, DocumentedBoundsAreAccepted) {
    nlohmann::json j = valid_scene();
    j["materials"][1]["roughness"] = 0.001;
    EXPECT_EQ(error_of(j), "<no error>");
    j["materials"][1]["roughness"] = 0.0009;
    EXPECT_NE(error_of(j).find("allowed in [0.001, 1]"), std::string::npos) << error_of(j);
    // Dielectric eta is (1, 4]: 1 itself is rejected, anything above accepted.
    nlohmann::json d = valid_scene();
    d["materials"][0] = {{"name", "d"}, {"type", "dielectric"}, {"eta", 1.00001}};
    d["shapes"][0]["material"] = "d";
    EXPECT_EQ(error_of(d), "<no error>");
    d["materials"][0]["eta"] = 1.0;
    EXPECT_NE(error_of(d).find("/materials/0/eta: value 1 out of range: allowed in (1, 4]"),
              std::string::npos)
        << error_of(d);
}

// Generated grid meshes are checked against the memory limit before they
// are built (a 4096² heightfield is about 1 GiB): the error names the file,
// the shape's JSON path, the size and the limit. The estimate is exact
// arithmetic: 4097² vertices × 36 bytes + 2·4096² triangles × 12 bytes =
// 604 MiB + 384 MiB = 988 MiB, above a 512 MiB limit and below 1 GiB.
TEST(SceneLoader, GridMeshesAboveTheMemoryLimitAreRejectedBeforeBuilding) {
    set_memory_limit(uint64_t(512) << 20);
    nlohmann::json j = valid_scene();
    j["shapes"][0] = {{"type", "heightfield"}, {"resolution", 4096}, {"material", "floor"}};
    const std::string m = error_of(j);
    EXPECT_NE(m.find("bad.json: /shapes/0 (heightfield of resolution 4096x4096) needs about"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("more than the memory limit of 512.0 MiB (set by --memory-limit)"),
              std::string::npos)
        << m;
    j["shapes"][0] = {{"type", "torus"},
                      {"segments_major", 8192},
                      {"segments_minor", 8192},
                      {"material", "floor"}};
    EXPECT_NE(error_of(j).find("/shapes/0 (torus of segments 8192x8192)"), std::string::npos)
        << error_of(j);
    j["shapes"][0] = {
        {"type", "head"}, {"segments_phi", 8192}, {"rings_theta", 8192}, {"material", "floor"}};
    EXPECT_NE(error_of(j).find("/shapes/0 (head of segments x rings 8192x8192)"), std::string::npos)
        << error_of(j);
    // A small grid passes and is built.
    set_memory_limit(uint64_t(1) << 30);
    j["shapes"][0] = {{"type", "heightfield"}, {"resolution", 8}, {"material", "floor"}};
    EXPECT_EQ(error_of(j), "<no error>");
    set_memory_limit(std::nullopt);
}

// A height image outside [0, 1] (an EXR of 1e30, a negative texel) was
// accepted and the geometry vanished: the error names the scene, the key, the
// image and the pixel.
TEST(SceneLoader, HeightImageOutsideTheUnitRangeIsAnError) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("glintlab_heights_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    Image img(4, 4);
    for (auto& p : img.pixels) p = glm::vec3(0.5f);
    write_exr(img, dir / "ok.exr");
    img.at(2, 1) = glm::vec3(1e30f);
    write_exr(img, dir / "huge.exr");
    img.at(2, 1) = glm::vec3(-0.25f);
    write_exr(img, dir / "negative.exr");
    nlohmann::json j = valid_scene();
    j["shapes"][0] = {{"type", "heightfield"}, {"resolution", 8}, {"material", "floor"}};
    j["shapes"][0]["file"] = (dir / "ok.exr").string();
    EXPECT_EQ(error_of(j), "<no error>");
    for (const char* name : {"huge.exr", "negative.exr"}) {
        j["shapes"][0]["file"] = (dir / name).string();
        const std::string m = error_of(j);
        EXPECT_NE(m.find("bad.json: /shapes/0/file: "), std::string::npos) << m;
        EXPECT_NE(m.find(std::string(name) + ": height image luminance"), std::string::npos) << m;
        EXPECT_NE(m.find("at pixel (2, 1) out of range: heights must lie in [0, 1]"),
                  std::string::npos)
            << m;
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace glintlab
