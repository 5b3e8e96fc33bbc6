// OpenEXR reading: compressions, channel layouts, windows, and the CC0
// studio lights that ship with Blender (Poly Haven style half/DWAB maps).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfTiledRgbaFile.h>
#include <gtest/gtest.h>

#include "glintlab/core/image.h"
#include "glintlab/core/image_test_util.h"

namespace glintlab {
namespace {

using testing::ScratchDir;

const std::filesystem::path kStudioLights = "/usr/share/blender/datafiles/studiolights/world";

// A smooth HDR test pattern (0.05 .. ~20, distinct per channel) like an environment map.
std::vector<Imf::Rgba> smooth_rgba(int w, int h) {
    std::vector<Imf::Rgba> px(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float u = float(x) / float(w), v = float(y) / float(h);
            px[size_t(y) * size_t(w) + size_t(x)] =
                Imf::Rgba(0.05f + 20.0f * u * u, 1.0f + 0.5f * std::sin(6.0f * v),
                          0.3f + 0.2f * std::cos(4.0f * (u + v)), 0.5f);
        }
    }
    return px;
}

void write_rgba(const std::filesystem::path& path, const std::vector<Imf::Rgba>& px, int w, int h,
                Imf::Compression compression) {
    Imf::RgbaOutputFile file(path.c_str(), w, h, Imf::WRITE_RGBA, 1.0f, Imath::V2f(0, 0), 1.0f,
                             Imf::INCREASING_Y, compression);
    file.setFrameBuffer(px.data(), 1, size_t(w));
    file.writePixels(h);
}

// Half values pass through the lossless codecs bit-exactly; alpha is dropped.
TEST(ImageExrRead, LosslessCompressionsAreExact) {
    ScratchDir dir;
    const int w = 45, h = 33;  // not multiples of the 16/32-line blocks or 8x8 DCT tiles
    const auto px = smooth_rgba(w, h);
    for (auto [compression, name] :
         {std::pair{Imf::NO_COMPRESSION, "none"}, std::pair{Imf::ZIP_COMPRESSION, "zip"},
          std::pair{Imf::ZIPS_COMPRESSION, "zips"}, std::pair{Imf::PIZ_COMPRESSION, "piz"},
          std::pair{Imf::RLE_COMPRESSION, "rle"}}) {
        const auto path = dir / (std::string(name) + ".exr");
        write_rgba(path, px, w, h, compression);
        const Image image = read_image(path);
        ASSERT_EQ(image.width, w);
        ASSERT_EQ(image.height, h);
        for (size_t i = 0; i < px.size(); ++i)
            ASSERT_EQ(image.pixels[i], glm::vec3(px[i].r, px[i].g, px[i].b)) << name << " " << i;
    }
}

// DWAA (32-line blocks) and DWAB (256-line blocks) quantise 8x8 DCT blocks of a
// perceptually encoded signal (a 2.2 power below 1, log-like above). At the
// default level 45 the step is meant to be near a just-noticeable difference,
// about 0.5% of the encoded value; through the 2.2 power that becomes a relative
// error of ~1.1% in linear light, largest on the darkest pixels (here 0.05).
// We allow two such steps per pixel (2.5%), 0.5% mean relative error, and 0.2%
// on the image mean (DC terms are quantised most finely). Measured: max 1.5%,
// mean 0.2% (on pixels of value ~0.1).
TEST(ImageExrRead, DwaCompressionsWithinPerceptualTolerance) {
    ScratchDir dir;
    const int w = 80, h = 300;  // taller than one DWAB block of 256 lines
    const auto px = smooth_rgba(w, h);
    for (auto [compression, name] :
         {std::pair{Imf::DWAA_COMPRESSION, "dwaa"}, std::pair{Imf::DWAB_COMPRESSION, "dwab"}}) {
        const auto path = dir / (std::string(name) + ".exr");
        write_rgba(path, px, w, h, compression);
        EXPECT_EQ(Imf::InputFile(path.c_str()).header().compression(), compression);
        const Image image = read_image(path);
        ASSERT_EQ(image.width, w);
        ASSERT_EQ(image.height, h);
        double max_rel = 0.0, sum_rel = 0.0;
        glm::dvec3 sum_in(0.0), sum_out(0.0);
        for (size_t i = 0; i < px.size(); ++i) {
            const glm::vec3 want(px[i].r, px[i].g, px[i].b);
            for (int c = 0; c < 3; ++c) {
                const double rel = std::abs(image.pixels[i][c] - want[c]) / want[c];
                max_rel = std::max(max_rel, rel);
                sum_rel += rel;
            }
            sum_in += glm::dvec3(want);
            sum_out += glm::dvec3(image.pixels[i]);
        }
        EXPECT_LT(max_rel, 0.025) << name;
        EXPECT_LT(sum_rel / (3.0 * double(px.size())), 0.005) << name;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(sum_out[c] / sum_in[c], 1.0, 0.002) << name << " channel " << c;
        RecordProperty(std::string(name) + "_max_rel_error", std::to_string(max_rel));
    }
}

// Float32 data is read at full precision (no detour through half, which would turn
// 1e6 into infinity and round 1/3).
TEST(ImageExrRead, FloatLuminanceOnlyBecomesGrey) {
    ScratchDir dir;
    const int w = 5, h = 4;
    std::vector<float> y(size_t(w * h));
    for (size_t i = 0; i < y.size(); ++i) y[i] = float(i) / 3.0f + (i == 7 ? 1e6f : 0.0f);
    Imf::Header header(w, h);
    header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
    header.compression() = Imf::PIZ_COMPRESSION;
    Imf::FrameBuffer frame;
    frame.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(y.data()), sizeof(float),
                                 sizeof(float) * w));
    {
        Imf::OutputFile out((dir / "y.exr").c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(h);
    }
    const Image image = read_image(dir / "y.exr");
    ASSERT_EQ(image.width, w);
    ASSERT_EQ(image.height, h);
    for (size_t i = 0; i < y.size(); ++i) EXPECT_EQ(image.pixels[i], glm::vec3(y[i])) << i;
}

// The image is the display window; a data window offset inside it lands at its
// offset, the rest stays black; a data window overhanging it is cropped.
TEST(ImageExrRead, DataWindowPlacedInDisplayWindow) {
    ScratchDir dir;
    const Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(7, 5));  // 8 x 6
    const Imath::Box2i data(Imath::V2i(2, 1), Imath::V2i(9, 4));     // x 2..9 overhangs by 2
    const int dw = 8, dh = 4;
    std::vector<Imf::Rgba> px(size_t(dw * dh));
    for (int i = 0; i < dw * dh; ++i) px[size_t(i)] = Imf::Rgba(float(i + 1), 0.5f, 0.25f, 1.0f);
    {
        Imf::Header header(display, data);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::RgbaOutputFile out((dir / "win.exr").c_str(), header, Imf::WRITE_RGB);
        // Base pointer for absolute coordinates of the data window's origin (2, 1).
        const intptr_t shift = intptr_t(2 + 1 * dw) * intptr_t(sizeof(Imf::Rgba));
        out.setFrameBuffer(
            reinterpret_cast<Imf::Rgba*>(reinterpret_cast<intptr_t>(px.data()) - shift), 1,
            size_t(dw));
        out.writePixels(dh);
    }
    const Image image = read_image(dir / "win.exr");
    ASSERT_EQ(image.width, 8);
    ASSERT_EQ(image.height, 6);
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 8; ++x) {
            const bool inside = x >= 2 && y >= 1 && y <= 4;
            const glm::vec3 want =
                inside ? glm::vec3(float((y - 1) * dw + (x - 2) + 1), 0.5f, 0.25f) : glm::vec3(0);
            EXPECT_EQ(image.at(x, y), want) << x << "," << y;
        }
    }
}

TEST(ImageExrRead, TiledFiles) {
    ScratchDir dir;
    const int w = 50, h = 20;
    const auto px = smooth_rgba(w, h);
    {
        Imf::TiledRgbaOutputFile out((dir / "tiled.exr").c_str(), w, h, 16, 16, Imf::ONE_LEVEL,
                                     Imf::ROUND_DOWN, Imf::WRITE_RGB, 1.0f, Imath::V2f(0, 0), 1.0f,
                                     Imf::INCREASING_Y, Imf::PIZ_COMPRESSION);
        out.setFrameBuffer(px.data(), 1, size_t(w));
        out.writeTiles(0, out.numXTiles() - 1, 0, out.numYTiles() - 1);
    }
    const Image image = read_image(dir / "tiled.exr");
    ASSERT_EQ(image.width, w);
    for (size_t i = 0; i < px.size(); ++i)
        ASSERT_EQ(image.pixels[i], glm::vec3(px[i].r, px[i].g, px[i].b)) << i;
}

// Blender's CC0 studio lights: 1024x512 float32 RGB, all DWAB-compressed (checked below),
// like Poly Haven downloads. Cross-check our decode against OpenEXR's RGBA interface,
// an independent code path that delivers the same pixels rounded to half.
TEST(ImageExrRead, BlenderStudioLightsDwab) {
    const std::vector<std::string> names = {"city",  "courtyard", "forest",  "interior",
                                            "night", "studio",    "sunrise", "sunset"};
    if (!std::filesystem::exists(kStudioLights / "studio.exr"))
        GTEST_SKIP() << "blender-data not installed";
    for (const std::string& name : names) {
        const auto path = kStudioLights / (name + ".exr");
        Imf::RgbaInputFile reference(path.c_str());
        EXPECT_EQ(reference.header().compression(), Imf::DWAB_COMPRESSION) << name;
        EXPECT_EQ(reference.header().channels().findChannel("R")->type, Imf::FLOAT) << name;
        const Image image = read_image(path);
        ASSERT_EQ(image.width, 1024) << name;
        ASSERT_EQ(image.height, 512) << name;
        std::vector<Imf::Rgba> px(size_t(1024 * 512));
        reference.setFrameBuffer(px.data(), 1, 1024);
        reference.readPixels(0, 511);
        double sum = 0.0;
        for (size_t i = 0; i < px.size(); ++i) {
            // Same codec, so rounding our floats to half must give the reference bits exactly.
            const glm::vec3& p = image.pixels[i];
            ASSERT_EQ(half(p.x).bits(), px[i].r.bits()) << name << " " << i;
            ASSERT_EQ(half(p.y).bits(), px[i].g.bits()) << name << " " << i;
            ASSERT_EQ(half(p.z).bits(), px[i].b.bits()) << name << " " << i;
            sum += luminance(image.pixels[i]);
        }
        EXPECT_GT(sum, 0.0) << name;
    }
}

}  // namespace
}  // namespace glintlab
