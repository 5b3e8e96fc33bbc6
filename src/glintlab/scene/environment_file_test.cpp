// Environment images read from files: negative texels are clamped with one
// warning, texels beyond the radiance limit and non-finite texels are errors
// naming the file and the texel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/image_test_util.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/renderer.h"
#include "glintlab/scene/environment_file.h"

namespace glintlab {
namespace {

using glintlab::testing::ScratchDir;

// Writes RGB float EXR with OpenEXR directly (write_image refuses NaN).
void write_raw_exr(const Image& image, const std::filesystem::path& path) {
    Imf::Header header(image.width, image.height);
    Imf::FrameBuffer frame;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        frame.insert(
            names[c],
            Imf::Slice(Imf::FLOAT,
                       const_cast<char*>(reinterpret_cast<const char*>(&image.pixels[0][c])),
                       sizeof(glm::vec3), image.width * sizeof(glm::vec3)));
    }
    Imf::OutputFile out(path.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(image.height);
}

// A 32x16 sky of radiance 1 whose lower half (the ground) has strongly
// negative red and green, as a ringing resampler would leave; texels with
// several negative components count once.
Image negative_sky(size_t* negatives) {
    Image image(32, 16, glm::vec3(1.0f));
    *negatives = 0;
    for (int y = 8; y < 16; ++y)
        for (int x = 0; x < 32; ++x) {
            image.at(x, y) = glm::vec3(-3.0f, x % 2 == 0 ? -2.0f : 0.5f, 0.25f);
            ++*negatives;
        }
    image.at(5, 2) = glm::vec3(2.0f, -0.0f, 1.0f);  // −0 is not negative
    return image;
}

// A diffuse sphere under the environment, the map visible around it.
nlohmann::json env_scene(const std::string& file, double scale = 1.0) {
    return {{"film", {{"width", 24}, {"height", 16}}},
            {"camera", {{"eye", {0, 0.5, 4}}, {"target", {0, 0, 0}}, {"fov_deg", 60}}},
            {"render", {{"spp", 2}, {"max_depth", 3}}},
            {"materials", {{{"name", "clay"}, {"type", "diffuse"}, {"albedo", 0.7}}}},
            {"shapes", {{{"type", "sphere"}, {"radius", 1}, {"material", "clay"}}}},
            {"lights", {{{"type", "environment"}, {"file", file}, {"scale", scale}}}}};
}

void expect_error(const std::function<void()>& f, const std::vector<std::string>& fragments) {
    try {
        f();
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        const std::string message = e.what();
        for (const std::string& fragment : fragments)
            EXPECT_NE(message.find(fragment), std::string::npos) << message << " / " << fragment;
    }
}

TEST(EnvironmentFile, NegativeTexelsAreClampedWithOneWarning) {
    ScratchDir dir;
    size_t expected = 0;
    write_image(negative_sky(&expected), dir / "negative.exr");
    size_t count = 0;
    ::testing::internal::CaptureStderr();
    const Image image = read_environment_image(dir / "negative.exr", 1.0f, &count);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(count, expected);
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find("negative.exr"), std::string::npos) << err;
    EXPECT_NE(err.find(std::to_string(expected) + " environment texels"), std::string::npos) << err;
    for (const glm::vec3& p : image.pixels) EXPECT_GE(std::min({p.x, p.y, p.z}), 0.0f);
    EXPECT_EQ(image.at(0, 8), glm::vec3(0.0f, 0.0f, 0.25f));  // clamped, not dropped
    EXPECT_EQ(image.at(1, 8), glm::vec3(0.0f, 0.5f, 0.25f));

    // A clean map loads silently.
    write_image(Image(8, 4, glm::vec3(0.5f)), dir / "clean.exr");
    ::testing::internal::CaptureStderr();
    read_environment_image(dir / "clean.exr", 1.0f, &count);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(count, 0u);
}

// Unclamped, the ground's −3 red would reach the camera directly (pixels
// below the horizon) and through the diffuse sphere: negative pixels.
TEST(EnvironmentFile, NegativeTexelsRenderNoNegativePixel) {
    ScratchDir dir;
    size_t expected = 0;
    write_image(negative_sky(&expected), dir / "negative.exr");
    ::testing::internal::CaptureStderr();
    const Scene scene = parse_scene(env_scene("negative.exr"), dir / "scene.json");
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find(std::to_string(expected) + " environment texels"), std::string::npos) << err;
    const Image image = render_scene(scene, RenderOptions{1, true});
    for (const glm::vec3& p : image.pixels) {
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        ASSERT_GE(std::min({p.x, p.y, p.z}), 0.0f);
    }
}

// Texels at the limit (1e20) render finite pixels; beyond it (3e38, which
// overflows float sums to inf and then NaN), or beyond it after the scale,
// the load fails naming the file, the texel and the limit.
TEST(EnvironmentFile, HugeTexelsHaveADocumentedLimit) {
    ScratchDir dir;
    Image image(16, 8, glm::vec3(1.0f));
    image.at(3, 2) = glm::vec3(static_cast<float>(kMaxEnvironmentRadiance));
    write_image(image, dir / "limit.exr");
    const Image render = render_scene(parse_scene(env_scene("limit.exr"), dir / "scene.json"),
                                      RenderOptions{1, true});
    for (const glm::vec3& p : render.pixels)
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));

    image.at(3, 2) = glm::vec3(3e38f);
    write_image(image, dir / "huge.exr");
    expect_error([&] { parse_scene(env_scene("huge.exr"), dir / "scene.json"); },
                 {"huge.exr", "(x=3, y=2)", "1e+20"});
    // 1e15 is fine alone but 1e15 × scale 1e6 = 1e21 is over the limit.
    image.at(3, 2) = glm::vec3(1e15f);
    write_image(image, dir / "bright.exr");
    EXPECT_NO_THROW(parse_scene(env_scene("bright.exr"), dir / "scene.json"));
    expect_error([&] { parse_scene(env_scene("bright.exr", 1e6), dir / "scene.json"); },
                 {"bright.exr", "(x=3, y=2)", "scale 1000000", "1e+20"});
}

TEST(EnvironmentFile, NonFiniteTexelIsAnErrorNamingFileAndTexel) {
    ScratchDir dir;
    Image image(16, 8, glm::vec3(1.0f));
    image.at(6, 1).z = std::nanf("");
    write_raw_exr(image, dir / "nan.exr");
    expect_error([&] { parse_scene(env_scene("nan.exr"), dir / "scene.json"); },
                 {"nan.exr", "x=6, y=1", "non-finite"});
    image.at(6, 1).z = -INFINITY;
    write_raw_exr(image, dir / "inf.exr");
    expect_error([&] { parse_scene(env_scene("inf.exr"), dir / "scene.json"); },
                 {"inf.exr", "x=6, y=1", "non-finite"});
}

}  // namespace
}  // namespace glintlab
