// The texture form of material parameters (docs/SCENE_FORMAT.md,
// "Textures"): values, colour spaces, channels, and the errors a user meets.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <nlohmann/json.hpp>

#include "glintlab/core/image.h"
#include "glintlab/glints/glint_textures.h"
#include "glintlab/glints/registry.h"
#include "glintlab/loader/scene_loader.h"

namespace glintlab {
namespace {

struct TextureScene {
    std::filesystem::path dir;
    TextureScene() {
        dir = std::filesystem::temp_directory_path() /
              ("glintlab_textures_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
        // 4x2 EXR: ln N 8 on the left half, 12 on the right.
        Image density(4, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 4; ++x) density.at(x, y) = glm::vec3(x < 2 ? 8.0f : 12.0f);
        write_exr(density, dir / "density.exr");
        Image grey(2, 2, glm::vec3(0.25f));  // PNG codes round(255 srgb(0.25)) = 137
        write_png(grey, dir / "grey.png");
        Image colour(2, 2, glm::vec3(0.25f, 0.5f, 0.75f));
        write_png(colour, dir / "colour.png");
    }
    ~TextureScene() { std::filesystem::remove_all(dir); }

    nlohmann::json scene(const nlohmann::json& material) const {
        nlohmann::json m = material;
        m["name"] = "m";
        if (m["type"] == "glint" && !m.contains("model")) m["model"] = "smooth";
        return {{"camera", {{"eye", {0, 1, 3}}, {"target", {0, 0, 0}}}},
                {"film", {{"width", 8}, {"height", 8}}},
                {"materials", {m}},
                {"shapes", {{{"type", "quad"}, {"size", {2, 2}}, {"material", "m"}}}},
                {"lights", {{{"type", "directional"}, {"direction", {0, 1, 0}}}}}};
    }
    Scene load(const nlohmann::json& material) const {
        return parse_scene(scene(material), dir / "scene.json");
    }
    std::string error(const nlohmann::json& material) const {
        try {
            load(material);
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    }
};

TEST(TextureReader, DensityMapIsFilteredAsFacetsPerAreaAndReadBackAsItsLog) {
    const TextureScene t;
    const Scene s = t.load({{"type", "glint"},
                            {"model", "deliot2023"},
                            {"log_density", {{"texture", "density.exr"}, {"wrap", "clamp"}}}});
    const GlintDesc& g = s.materials[0].glint;
    ASSERT_TRUE(g.textures && g.textures->density);
    // Texel centres: ln N itself.
    EXPECT_NEAR(resolve_glint_textures(g, {0.125f, 0.5f}, nullptr).log_density, 8.0f, 1e-4f);
    EXPECT_NEAR(resolve_glint_textures(g, {0.875f, 0.5f}, nullptr).log_density, 12.0f, 1e-4f);
    // A footprint over the whole map: ln of the mean N, not the mean ln N.
    const Footprint whole{{0.5f, 0.5f}, {1.0f, 0.0f}, {0.0f, 1.0f}};
    EXPECT_NEAR(resolve_glint_textures(g, {0.5f, 0.5f}, &whole).log_density,
                std::log(0.5 * (std::exp(8.0) + std::exp(12.0))), 1e-3);
}

TEST(TextureReader, DensityAndRoughnessMapsThatLineUpAreReadByOneLookup) {
    const TextureScene t;
    Image rough(4, 2);  // α 0.1 on the left half, 0.4 on the right
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) rough.at(x, y) = glm::vec3(x < 2 ? 0.1f : 0.4f);
    write_exr(rough, t.dir / "rough.exr");
    auto glint = [&](const char* rough_wrap) {
        return t.load({{"type", "glint"},
                       {"model", "deliot2023"},
                       {"log_density", {{"texture", "density.exr"}}},
                       {"roughness", {{"texture", "rough.exr"}, {"wrap", rough_wrap}}}});
    };
    const Scene packed = glint("repeat"), apart = glint("clamp");
    const GlintTextures& p = *packed.materials[0].glint.textures;
    EXPECT_EQ(p.density->texture, p.alpha_x_sq->texture);
    EXPECT_EQ(p.alpha_x_sq, p.alpha_y_sq);
    EXPECT_EQ(p.density->texture->channels(), 2);
    const GlintTextures& a = *apart.materials[0].glint.textures;
    EXPECT_NE(a.density->texture, a.alpha_x_sq->texture);
    // The same values either way (away from the edge, where the wraps differ).
    const GlintDesc& gp = packed.materials[0].glint;
    const GlintDesc& ga = apart.materials[0].glint;
    for (const glm::vec2 uv : {glm::vec2(0.125f, 0.5f), glm::vec2(0.875f, 0.5f)}) {
        const GlintDesc rp = resolve_glint_textures(gp, uv, nullptr);
        const GlintDesc ra = resolve_glint_textures(ga, uv, nullptr);
        EXPECT_EQ(rp.log_density, ra.log_density);
        EXPECT_EQ(rp.alpha_x, ra.alpha_x);
        EXPECT_EQ(rp.alpha_y, ra.alpha_y);
    }
    const GlintDesc left = resolve_glint_textures(gp, {0.125f, 0.5f}, nullptr);
    EXPECT_NEAR(left.log_density, 8.0f, 1e-4f);
    EXPECT_NEAR(left.alpha_x, 0.1f, 1e-5f);
    const Footprint mid{{0.5f, 0.25f}, {0.25f, 0.0f}, {0.0f, 0.25f}};
    const GlintDesc centre = resolve_glint_textures(gp, mid.uv, &mid);
    EXPECT_EQ(centre.log_density, resolve_glint_textures(ga, mid.uv, &mid).log_density);
    EXPECT_EQ(centre.alpha_y, resolve_glint_textures(ga, mid.uv, &mid).alpha_y);
    // A glTF-style metallic-roughness map: roughness (g) and metallic (b) of one image.
    const Scene mr = t.load({{"type", "metallic_roughness"},
                             {"roughness", {{"texture", "colour.png"}, {"channel", "g"}}},
                             {"metallic", {{"texture", "colour.png"}, {"channel", "b"}}}});
    const MaterialTextures& mt = *mr.materials[0].textures;
    EXPECT_EQ(mt.metallic->texture, mt.alpha_x_sq->texture);
    EXPECT_EQ(mt.metallic->channel, 0);
    EXPECT_EQ(mt.alpha_x_sq->channel, 1);
}

TEST(TextureReader, PngDataIsLinearCodesAndColourIsSrgbDecoded) {
    const TextureScene t;
    const Scene s = t.load({{"type", "glint"},
                            {"model", "smooth"},
                            {"roughness", {{"texture", "grey.png"}}},
                            {"color", {{"texture", "colour.png"}}}});
    const GlintDesc r = resolve_glint_textures(s.materials[0].glint, {0.3f, 0.3f}, nullptr);
    const float code = std::round(255.0f * srgb_encode(0.25f)) / 255.0f;
    EXPECT_NEAR(r.alpha_x, code, 1e-5f);
    EXPECT_NEAR(r.alpha_y, code, 1e-5f);
    EXPECT_NEAR(r.color.x, 0.25f, 0.004f);
    EXPECT_NEAR(r.color.z, 0.75f, 0.004f);
    // scale and offset: value = offset + scale x texel.
    const Scene s2 =
        t.load({{"type", "glint"},
                {"model", "smooth"},
                {"roughness", {{"texture", "grey.png"}, {"scale", 0.5}, {"offset", 0.1}}}});
    EXPECT_NEAR(resolve_glint_textures(s2.materials[0].glint, {0.3f, 0.3f}, nullptr).alpha_x,
                0.1f + 0.5f * code, 1e-5f);
}

TEST(TextureReader, DiffuseAlbedoAndConductorRoughnessTakeTextures) {
    const TextureScene t;
    const Scene d = t.load({{"type", "diffuse"}, {"albedo", {{"texture", "colour.png"}}}});
    ASSERT_TRUE(d.materials[0].textures && d.materials[0].textures->albedo);
    EXPECT_TRUE(d.materials[0].needs_uv());
    const Scene c =
        t.load({{"type", "conductor"}, {"roughness", {{{"texture", "grey.png"}}, 0.2}}});
    ASSERT_TRUE(c.materials[0].textures);
    EXPECT_TRUE(c.materials[0].textures->alpha_x_sq);
    EXPECT_FALSE(c.materials[0].textures->alpha_y_sq);
    EXPECT_FLOAT_EQ(c.materials[0].alpha_y, 0.2f);
}

TEST(TextureReader, ErrorsNameTheFileTheJsonPathAndTheRange) {
    const TextureScene t;
    const std::string missing =
        t.error({{"type", "glint"}, {"roughness", {{"texture", "no.png"}}}});
    EXPECT_NE(missing.find("/materials/0/roughness/texture"), std::string::npos) << missing;
    EXPECT_NE(missing.find("no.png"), std::string::npos) << missing;

    const std::string range = t.error(
        {{"type", "glint"}, {"log_density", {{"texture", "density.exr"}, {"scale", 10.0}}}});
    EXPECT_NE(range.find("density.exr"), std::string::npos) << range;
    EXPECT_NE(range.find("/materials/0/log_density"), std::string::npos) << range;
    EXPECT_NE(range.find("[-20, 60]"), std::string::npos) << range;

    const std::string channel =
        t.error({{"type", "glint"}, {"roughness", {{"texture", "colour.png"}}}});
    EXPECT_NE(channel.find("\"channel\""), std::string::npos) << channel;
    const std::string rgb =
        t.error({{"type", "glint"}, {"roughness", {{"texture", "grey.png"}, {"channel", "rgb"}}}});
    EXPECT_NE(rgb.find("single value"), std::string::npos) << rgb;
    const std::string srgb = t.error(
        {{"type", "glint"}, {"log_density", {{"texture", "density.exr"}, {"colorspace", "srgb"}}}});
    EXPECT_NE(srgb.find("linear values"), std::string::npos) << srgb;
    const std::string wrap =
        t.error({{"type", "glint"}, {"roughness", {{"texture", "grey.png"}, {"wrap", "tile"}}}});
    EXPECT_NE(wrap.find("mirror"), std::string::npos) << wrap;
    for (const nlohmann::json& bad :
         {nlohmann::json::array({"repeat"}), nlohmann::json::array({"repeat", "tile"}),
          nlohmann::json::array({"clamp", "clamp", "clamp"})}) {
        const std::string e =
            t.error({{"type", "glint"}, {"roughness", {{"texture", "grey.png"}, {"wrap", bad}}}});
        EXPECT_NE(e.find("/materials/0/roughness/wrap"), std::string::npos) << e;
        EXPECT_NE(e.find("[along u, along v]"), std::string::npos) << e;
    }
    const Scene apart =
        t.load({{"type", "glint"},
                {"roughness",
                 {{"texture", "grey.png"}, {"wrap", nlohmann::json::array({"mirror", "clamp"})}}}});
    ASSERT_TRUE(apart.materials[0].glint.textures && apart.materials[0].glint.textures->alpha_x_sq);
    EXPECT_EQ(apart.materials[0].glint.textures->alpha_x_sq->texture->wrap(),
              (TextureWraps{TextureWrap::Mirror, TextureWrap::Clamp}));
    const std::string unknown =
        t.error({{"type", "glint"}, {"roughness", {{"texture", "grey.png"}, {"gamma", 2}}}});
    EXPECT_NE(unknown.find("gamma"), std::string::npos) << unknown;
    // A model that precomputes per material says why it cannot.
    const std::string model = t.error(
        {{"type", "glint"}, {"model", "wang2020"}, {"log_density", {{"texture", "density.exr"}}}});
    EXPECT_NE(model.find("cannot take \"log_density\" from a texture"), std::string::npos) << model;
    // The paths that take numbers only say so instead of drawing the wrong image.
    const Scene s = t.load({{"type", "glint"}, {"roughness", {{"texture", "grey.png"}}}});
    try {
        require_untextured(s.materials[0], s.file, "the OpenGL renderer");
        ADD_FAILURE() << "no error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("reads roughness from a texture"), std::string::npos)
            << e.what();
    }
}

// A file's own defects: a non-finite texel (EXR holds NaN and Inf) and a
// format no reader takes are errors naming the file, the texel or the
// formats, and the JSON path that asked for the texture.
TEST(TextureReader, NonFiniteTexelsAndUnsupportedFormatsAreErrors) {
    const TextureScene t;
    // write_exr refuses such pixels: OpenEXR's own writer, one channel.
    auto write_raw_exr = [&](const char* name, int x, int y, float value) {
        std::vector<float> texels(9, 0.2f);
        texels[size_t(3 * y + x)] = value;
        Imf::Header header(3, 3);
        header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
        Imf::FrameBuffer frame;
        frame.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(texels.data()),
                                     sizeof(float), 3 * sizeof(float)));
        Imf::OutputFile out((t.dir / name).c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(3);
    };
    write_raw_exr("nan.exr", 2, 1, std::nanf(""));
    write_raw_exr("inf.exr", 0, 2, INFINITY);
    for (const auto& [file, texel] : {std::pair{"nan.exr", "x=2, y=1"}, {"inf.exr", "x=0, y=2"}}) {
        const std::string e = t.error({{"type", "glint"}, {"roughness", {{"texture", file}}}});
        EXPECT_NE(e.find(file), std::string::npos) << e;
        EXPECT_NE(e.find(texel), std::string::npos) << e;
        EXPECT_NE(e.find("non-finite"), std::string::npos) << e;
        EXPECT_NE(e.find("/materials/0/roughness"), std::string::npos) << e;
    }
    {
        std::ofstream tga(t.dir / "tiles.tga", std::ios::binary);
        tga << std::string(64, '\0');
    }
    const std::string format =
        t.error({{"type", "diffuse"}, {"albedo", {{"texture", "tiles.tga"}}}});
    EXPECT_NE(format.find("tiles.tga"), std::string::npos) << format;
    EXPECT_NE(format.find("/materials/0/albedo"), std::string::npos) << format;
    EXPECT_NE(format.find(".png"), std::string::npos) << format;  // names what it reads
}

// kneiphof2025's maps, tables and grids read α and ln N per hit, so it
// takes density and roughness maps; its tables are isotropic GGX, so a
// roughness is one texture for both axes, never an [α_x, α_y] pair.
TEST(TextureReader, Kneiphof2025TakesDensityAndOneRoughnessMap) {
    const TextureScene t;
    const Scene s = t.load({{"type", "glint"},
                            {"model", "kneiphof2025"},
                            {"ndf", "ggx"},
                            {"log_density", {{"texture", "density.exr"}}},
                            {"roughness", {{"texture", "grey.png"}}}});
    ASSERT_TRUE(s.materials[0].glint.textures);
    EXPECT_TRUE(s.materials[0].glint.textures->density);
    EXPECT_TRUE(s.materials[0].glint.textures->alpha_x_sq);
    EXPECT_EQ(s.materials[0].glint.textures->alpha_x_sq, s.materials[0].glint.textures->alpha_y_sq);
    const std::string pair = t.error({{"type", "glint"},
                                      {"model", "kneiphof2025"},
                                      {"ndf", "ggx"},
                                      {"roughness", {{{"texture", "grey.png"}}, 0.2}}});
    EXPECT_NE(pair.find("one roughness value or one roughness texture"), std::string::npos) << pair;
    EXPECT_NE(pair.find("/materials/0"), std::string::npos) << pair;
}

// glTF's maps: a perceptual roughness r is α = r² ("power": 2), a base
// colour factor scales each channel.
TEST(TextureReader, PowerSquaresTheValueAndAColourScaleHasOneFactorAChannel) {
    const TextureScene s;
    const Scene conductor =
        s.load({{"type", "conductor"},
                {"roughness", {{"texture", "grey.png"}, {"power", 2}, {"scale", 0.5}}}});
    const double r = 0.5 * 137.0 / 255.0;  // linear data: the code itself
    EXPECT_NEAR(conductor.materials[0].textures->alpha_x_sq->at({0.5f, 0.5f}).x, std::pow(r, 4.0),
                1e-6);  // stored as α² = r⁴
    const Scene paint =
        s.load({{"type", "metallic_roughness"},
                {"base_color", {{"texture", "colour.png"}, {"scale", {1.0, 0.5, 0.0}}}}});
    const glm::vec3 c = paint.materials[0].textures->albedo->at({0.5f, 0.5f});
    // sRGB codes of (0.25, 0.5, 0.75), decoded: within half a code's step.
    EXPECT_NEAR(c.x, 0.25f, 2e-3f);
    EXPECT_NEAR(c.y, 0.25f, 2e-3f);
    EXPECT_EQ(c.z, 0.0f);
    const std::string scalar = s.error(
        {{"type", "conductor"}, {"roughness", {{"texture", "grey.png"}, {"scale", {1, 1, 1}}}}});
    EXPECT_NE(scalar.find("/materials/0/roughness/scale"), std::string::npos) << scalar;
    EXPECT_NE(scalar.find("one factor a channel needs a colour parameter"), std::string::npos);
    const std::string cube =
        s.error({{"type", "conductor"}, {"roughness", {{"texture", "grey.png"}, {"power", 3}}}});
    EXPECT_NE(cube.find("/materials/0/roughness/power"), std::string::npos) << cube;
    const std::string range =
        s.error({{"type", "conductor"},
                 {"roughness", {{"texture", "grey.png"}, {"power", 2}, {"scale", 4.0}}}});
    EXPECT_NE(range.find("^2, outside the parameter's range [0, 1]"), std::string::npos) << range;
}

TEST(TextureReader, RoughnessBelowTheRangeIsClampedWithAWarning) {
    const TextureScene t;
    Image black(2, 2, glm::vec3(0.0f));
    write_png(black, t.dir / "black.png");
    testing::internal::CaptureStderr();
    const Scene s = t.load({{"type", "glint"}, {"roughness", {{"texture", "black.png"}}}});
    const std::string warning = testing::internal::GetCapturedStderr();
    EXPECT_NE(warning.find("4 texel values below 0.001 clamped"), std::string::npos) << warning;
    EXPECT_NEAR(resolve_glint_textures(s.materials[0].glint, {0.5f, 0.5f}, nullptr).alpha_x, 1e-3f,
                1e-7f);
    // A negative roughness is no 8-bit map's 0: an error, not a clamp.
    const std::string negative =
        t.error({{"type", "glint"}, {"roughness", {{"texture", "black.png"}, {"offset", -0.5}}}});
    EXPECT_NE(negative.find("/materials/0/roughness"), std::string::npos) << negative;
    EXPECT_NE(negative.find("maps to -0.5"), std::string::npos) << negative;
    EXPECT_NE(negative.find("outside the parameter's range [0.001, 1]"), std::string::npos)
        << negative;
}

// The viewer's model switcher: a model that cannot read a texture takes the
// whole map's mean instead (the number a scene file would give it).
TEST(TextureReader, SwitchingToAModelWithoutTexturedDensityUsesTheMapMean) {
    const TextureScene t;
    const Scene s = t.load({{"type", "glint"},
                            {"model", "deliot2023"},
                            {"log_density", {{"texture", "density.exr"}}},
                            {"color", {{"texture", "colour.png"}}}});
    GlintDesc g = s.materials[0].glint;
    switch_glint_model(g, GlintModelId::Wang2020);
    ASSERT_TRUE(g.textures);
    EXPECT_FALSE(g.textures->density);
    EXPECT_TRUE(g.textures->color);  // every model takes a colour texture
    EXPECT_NEAR(g.log_density, std::log(0.5 * (std::exp(8.0) + std::exp(12.0))), 1e-3);
}

}  // namespace
}  // namespace glintlab
