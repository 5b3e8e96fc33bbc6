#include "glintlab/core/image.h"

// A JPEG writer for the tests only (static: no clash with image_stb.cpp's).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <gtest/gtest.h>

// After the standard headers: jpeglib.h needs FILE and size_t declared.
#include <jpeglib.h>
#include <sys/resource.h>

#include "glintlab/core/error.h"
#include "glintlab/core/image_test_util.h"
#include "glintlab/core/memory_limit.h"

namespace glintlab {
namespace {

using testing::ScratchDir;

// Expects fn() to throw glintlab::Error whose message contains every needle.
template <typename Fn>
void expect_error(Fn fn, std::initializer_list<std::string> needles) {
    try {
        fn();
        ADD_FAILURE() << "no glintlab::Error thrown";
    } catch (const Error& e) {
        for (const std::string& n : needles)
            EXPECT_NE(std::string(e.what()).find(n), std::string::npos)
                << "message '" << e.what() << "' lacks '" << n << "'";
    }
}

// A deterministic image with values from 0 to ~4 and distinct channels.
Image ramp_image(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.at(x, y) = glm::vec3(4.0f * float(x) / float(w - 1), float(y) / float(h - 1),
                                       0.001f * float(x * y));
    return image;
}

TEST(ImageType, RowMajorTopLeftOrigin) {
    Image image(3, 2, glm::vec3(0.5f));
    EXPECT_EQ(image.pixels.size(), 6u);
    image.at(2, 1) = glm::vec3(7.0f);
    EXPECT_EQ(image.pixels[5], glm::vec3(7.0f));  // last pixel: x = width-1, y = height-1
    image.at(1, 0) = glm::vec3(3.0f);
    EXPECT_EQ(image.pixels[1], glm::vec3(3.0f));
    EXPECT_EQ(image.pixels[0], glm::vec3(0.5f));
}

TEST(ImageColor, LuminanceUsesRec709Weights) {
    // BT.709 weights; they sum to 1 so white has luminance 1 (float sum is exact to 1 ulp).
    EXPECT_FLOAT_EQ(luminance(glm::vec3(1.0f, 0.0f, 0.0f)), 0.2126f);
    EXPECT_FLOAT_EQ(luminance(glm::vec3(0.0f, 1.0f, 0.0f)), 0.7152f);
    EXPECT_FLOAT_EQ(luminance(glm::vec3(0.0f, 0.0f, 1.0f)), 0.0722f);
    EXPECT_NEAR(luminance(glm::vec3(1.0f)), 1.0f, 1e-6f);
}

TEST(ImageColor, SrgbCurvesMatchStandardAndInvert) {
    // Reference values from the IEC 61966-2-1 formulas evaluated in double precision.
    EXPECT_NEAR(srgb_encode(0.18f), 0.461356129500f, 1e-6f);
    EXPECT_NEAR(srgb_decode(0.5f), 0.214041140482f, 1e-6f);
    EXPECT_FLOAT_EQ(srgb_encode(1.0f), 1.0f);
    EXPECT_FLOAT_EQ(srgb_encode(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(srgb_encode(0.001f), 0.01292f);  // linear toe
    // The two pieces meet at 0.0031308 (encoded 0.04045) to within the constants' 5 digits.
    EXPECT_NEAR(1.055f * std::pow(0.0031308f, 1.0f / 2.4f) - 0.055f, 12.92f * 0.0031308f, 1e-6f);
    // Round trip: both curves are smooth with bounded slope on [0,1], so float rounding
    // (a few ulp at each pow) keeps the inverse within 1e-5 relative.
    for (int i = 0; i <= 1000; ++i) {
        const float x = float(i) / 1000.0f;
        EXPECT_NEAR(srgb_decode(srgb_encode(x)), x, 1e-5f * x + 1e-7f) << x;
    }
}

TEST(ImageExr, WriteExrIsLosslessFloatZip) {
    ScratchDir dir;
    const Image image = ramp_image(37, 23);
    const auto path = dir / "ramp.exr";
    write_exr(image, path);
    Imf::InputFile file(path.c_str());
    EXPECT_EQ(file.header().compression(), Imf::ZIP_COMPRESSION);
    for (const char* c : {"R", "G", "B"}) {
        ASSERT_NE(file.header().channels().findChannel(c), nullptr) << c;
        EXPECT_EQ(file.header().channels().findChannel(c)->type, Imf::FLOAT) << c;
    }
    const Image back = read_image(path);
    ASSERT_EQ(back.width, 37);
    ASSERT_EQ(back.height, 23);
    EXPECT_EQ(back.pixels, image.pixels);  // float32 + ZIP: bit-exact
}

TEST(ImagePng, RoundTripWithinHalfAnEightBitStep) {
    ScratchDir dir;
    const Image image = ramp_image(64, 8);
    for (float exposure : {0.0f, -1.5f}) {
        const auto path = dir / "ramp.png";
        write_png(image, path, exposure);
        const Image back = read_image(path);
        ASSERT_EQ(back.width, 64);
        ASSERT_EQ(back.height, 8);
        const float scale = std::exp2(exposure);
        for (size_t i = 0; i < image.pixels.size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                // Rounding to 8 bits moves the encoded value by at most half a step (1/510);
                // values above 1 after exposure clamp to white.
                const float want = std::min(srgb_encode(image.pixels[i][c] * scale), 1.0f);
                EXPECT_NEAR(srgb_encode(back.pixels[i][c]), want, 0.5f / 255.0f + 1e-5f)
                    << "pixel " << i << " channel " << c << " exposure " << exposure;
            }
        }
    }
}

TEST(ImagePng, ClampsAndDecodesExactCodes) {
    ScratchDir dir;
    Image image(3, 1);
    image.at(0, 0) = glm::vec3(-1.0f, 0.0f, 5.0f);  // below and above the displayable range
    image.at(1, 0) = glm::vec3(srgb_decode(128.0f / 255.0f));  // exactly code 128
    image.at(2, 0) = glm::vec3(0.25f);                         // exposure +2 stops -> 1.0
    write_png(image, dir / "c.png");
    Image back = read_image(dir / "c.png");
    EXPECT_EQ(back.at(0, 0), glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(back.at(1, 0), glm::vec3(srgb_decode(128.0f / 255.0f)));
    write_png(image, dir / "e.png", 2.0f);
    back = read_image(dir / "e.png");
    EXPECT_EQ(back.at(2, 0), glm::vec3(1.0f));
}

TEST(ImageHdr, RoundTripWithinRgbeMantissaPrecision) {
    ScratchDir dir;
    Image image = ramp_image(40, 10);
    image.at(3, 3) = glm::vec3(1000.0f, 0.5f, 20.0f);
    write_image(image, dir / "ramp.hdr");
    const Image back = read_image(dir / "ramp.hdr");
    ASSERT_EQ(back.width, 40);
    ASSERT_EQ(back.height, 10);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::vec3 p = image.pixels[i];
        // RGBE shares one exponent 2^e with max component in [2^(e-1), 2^e) and stores 8-bit
        // truncated mantissas, so each channel is off by less than 2^(e-8) <= max/128.
        const float bound = std::max({p.x, p.y, p.z}) / 128.0f + 1e-30f;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(back.pixels[i][c], p[c], bound) << i;
    }
}

TEST(ImageErrors, MissingUnknownEmptyAndCorruptFilesNameTheFile) {
    ScratchDir dir;
    const auto missing = dir / "nope.exr";
    expect_error([&] { read_image(missing); }, {missing.string(), "does not exist"});
    expect_error([&] { read_image(dir / "x.tiff"); }, {"x.tiff", "unknown", ".exr"});
    for (const char* name : {"empty.exr", "empty.png", "empty.hdr"}) {
        std::ofstream(dir / name).close();
        expect_error([&] { read_image(dir / name); }, {name, "empty"});
    }
    for (const char* name : {"junk.exr", "junk.png", "junk.hdr", "junk.jpg"}) {
        std::ofstream(dir / name) << "this is not an image file at all, just some text\n";
        expect_error([&] { read_image(dir / name); }, {name, "cannot read"});
    }
    // stb reads ten formats by content; only PNG and JPEG reach it. A PNM
    // header whose width overflows an int (undefined behaviour in stb's
    // reader, found by the image fuzzer) under a .png name, and a BMP: both
    // refused before stb parses them.
    std::ofstream(dir / "pnm.png", std::ios::binary) << "P5\n"
                                                     << std::string(40, '1') << " 1\n255\n";
    expect_error([&] { read_image(dir / "pnm.png"); },
                 {"pnm.png: cannot read PNG/JPEG file: it has neither the PNG signature"});
    std::ofstream(dir / "bmp.jpg", std::ios::binary) << "BM" << std::string(60, '\0');
    expect_error([&] { read_image(dir / "bmp.jpg"); }, {"bmp.jpg", "cannot read PNG/JPEG"});
    // A valid PNG under a .hdr name is not silently reinterpreted.
    write_png(Image(2, 2, glm::vec3(0.5f)), dir / "real.png");
    std::filesystem::copy_file(dir / "real.png", dir / "fake.hdr");
    expect_error([&] { read_image(dir / "fake.hdr"); }, {"fake.hdr"});
    // A truncated EXR (valid header, missing pixel data).
    write_exr(ramp_image(64, 64), dir / "full.exr");
    const auto size = std::filesystem::file_size(dir / "full.exr");
    std::filesystem::copy_file(dir / "full.exr", dir / "cut.exr");
    std::filesystem::resize_file(dir / "cut.exr", size / 2);
    expect_error([&] { read_image(dir / "cut.exr"); }, {"cut.exr"});
}

void put_be32(std::string& s, uint32_t v) {
    for (int b = 3; b >= 0; --b) s.push_back(static_cast<char>((v >> (8 * b)) & 0xff));
}

// A file's header can claim any size: a few hundred bytes claiming 60000² or
// 2³¹ pixels must be an error naming the file and the size before anything
// of that size is allocated (60000² × 12 bytes = 40 GiB, above the default
// limit of at most 8 GiB; the limit is set to 64 MiB here so the test never
// depends on the machine).
TEST(ImageErrors, HeaderSizesAreCheckedAgainstTheMemoryLimitBeforeAllocating) {
    ScratchDir dir;
    set_memory_limit(uint64_t(64) << 20);
    {
        // EXR: a 1x1 data window inside a 60000x60000 display window.
        const Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(59999, 59999));
        const Imath::Box2i data(Imath::V2i(0, 0), Imath::V2i(0, 0));
        Imf::Header header(display, data);
        header.channels().insert("R", Imf::Channel(Imf::FLOAT));
        float r = 1.0f;
        Imf::FrameBuffer frame;
        frame.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&r), sizeof r, sizeof r));
        Imf::OutputFile file((dir / "huge.exr").c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(1);
    }
    EXPECT_LT(std::filesystem::file_size(dir / "huge.exr"), 1000u);
    expect_error([&] { read_image(dir / "huge.exr"); },
                 {"huge.exr: reading the OpenEXR display window needs about", "image 60000x60000",
                  "more than the memory limit of 64.0 MiB"});
    // PNG: signature, an IHDR chunk claiming 16000x16000 RGB, IEND (stb reads
    // the size from IHDR before decoding).
    std::string png = "\x89PNG\r\n\x1a\n";
    put_be32(png, 13);
    png += "IHDR";
    put_be32(png, 16000);
    put_be32(png, 16000);
    png += std::string("\x08\x02\x00\x00\x00", 5);
    put_be32(png, 0);  // CRC (stb does not check it)
    put_be32(png, 0);
    png += "IEND";
    put_be32(png, 0);
    std::ofstream(dir / "huge.png", std::ios::binary) << png;
    expect_error([&] { read_image(dir / "huge.png"); },
                 {"huge.png: reading the PNG image needs about", "image 16000x16000"});
    // EXR: a header attribute declaring 1.5 GiB in a 30-byte file. OpenEXR
    // would allocate the declared size before reading; the reader refuses
    // first, naming the attribute (found by the image fuzzer).
    std::string exr("v/1\x01\x02\x00\x00\x00", 8);
    exr += std::string("foo\0bar\0", 8);
    exr += std::string("\x00\x00\x00\x60", 4);  // 0x60000000 bytes, little-endian
    exr += "0123456789";
    std::ofstream(dir / "attr.exr", std::ios::binary) << exr;
    expect_error([&] { read_image(dir / "attr.exr"); },
                 {"attr.exr: cannot read OpenEXR file: header attribute 'foo' of type 'bar' "
                  "declares 1610612736 bytes but only 10 bytes of the file follow it"});
    // PNG: a valid 4x4 IHDR, then an IDAT chunk declaring 1 GiB in a file of
    // 60 bytes (stb grew its buffer to the declared length before reading).
    std::string idat = "\x89PNG\r\n\x1a\n";
    put_be32(idat, 13);
    idat += "IHDR";
    put_be32(idat, 4);
    put_be32(idat, 4);
    idat += std::string("\x08\x02\x00\x00\x00", 5);
    put_be32(idat, 0);
    put_be32(idat, 1u << 30);
    idat += "IDAT0123456789";
    std::ofstream(dir / "idat.png", std::ios::binary) << idat;
    expect_error([&] { read_image(dir / "idat.png"); },
                 {"idat.png: cannot read PNG file: chunk 'IDAT' declares 1073741824 bytes but "
                  "only 10 bytes of the file follow it"});
    // EXR: a DWAB file 100000 pixels wide and one line high (0.4 MB of
    // pixels): opening it allocates a line buffer of a 256-line chunk,
    // 100000 x 256 x 4 bytes = 98 MiB, before any size check in read_exr ran
    // (the fuzzer's 33-million-pixel-wide window allocated a gigabyte).
    {
        const Imath::Box2i window(Imath::V2i(0, 0), Imath::V2i(99999, 0));
        Imf::Header header(window, window);
        header.compression() = Imf::DWAB_COMPRESSION;
        header.channels().insert("R", Imf::Channel(Imf::FLOAT));
        std::vector<float> row(100000, 0.5f);
        Imf::FrameBuffer frame;
        frame.insert("R",
                     Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(row.data()), sizeof(float), 0));
        Imf::OutputFile file((dir / "wide.exr").c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(1);
    }
    expect_error([&] { read_image(dir / "wide.exr"); },
                 {"wide.exr: opening the OpenEXR file needs about",
                  "OpenEXR line buffer (100000x256 pixels, 4 bytes a pixel)"});
    // A small image still reads under the small limit.
    write_png(Image(4, 4, glm::vec3(0.25f)), dir / "small.png");
    EXPECT_EQ(read_image(dir / "small.png").width, 4);
    set_memory_limit(std::nullopt);
}

// stb_image's Radiance decoder loops forever on a run of length 0, which is
// also what it reads past the end of a truncated file: both were hangs
// (found by the image fuzzer). A flat file cut short decoded as black.
TEST(ImageErrors, TruncatedOrCorruptHdrIsAnErrorNotAHang) {
    ScratchDir dir;
    write_hdr(ramp_image(16, 6), dir / "full.hdr");  // run-length encoded (width 16)
    EXPECT_EQ(read_image(dir / "full.hdr").width, 16);
    const auto size = std::filesystem::file_size(dir / "full.hdr");
    std::filesystem::copy_file(dir / "full.hdr", dir / "cut.hdr");
    std::filesystem::resize_file(dir / "cut.hdr", size - 20);
    expect_error([&] { read_image(dir / "cut.hdr"); },
                 {"cut.hdr: cannot read Radiance .hdr file: the pixel data ends in scanline",
                  "(truncated file)"});
    // One RLE scanline whose first run has length 0.
    std::string zero = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n";
    zero += std::string("\x02\x02\x00\x08\x00", 5);
    std::ofstream(dir / "zero.hdr", std::ios::binary) << zero;
    expect_error([&] { read_image(dir / "zero.hdr"); },
                 {"zero.hdr: cannot read Radiance .hdr file: a run of length 0 in scanline 0"});
    // Flat (width 4 < 8) data for 2 of 3 scanlines.
    std::string flat = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 3 +X 4\n";
    flat += std::string(4 * 4 * 2, '\x40');
    std::ofstream(dir / "flat.hdr", std::ios::binary) << flat;
    expect_error([&] { read_image(dir / "flat.hdr"); }, {"flat.hdr", "scanline 2 of 3"});
}

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void expect_same_pixels(const Image& a, const Image& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    for (size_t i = 0; i < a.pixels.size(); ++i) ASSERT_EQ(a.pixels[i], b.pixels[i]) << i;
}

// The image fuzzer's timeout: stb ends a .hdr header at a line starting with
// a NUL byte, not only at an empty line, and the pre-decode walk must start
// the pixel data where stb does.
TEST(ImageErrors, HdrHeaderEndsWhereStbEndsIt) {
    ScratchDir dir;
    write_hdr(ramp_image(16, 6), dir / "plain.hdr");
    std::string bytes = read_bytes(dir / "plain.hdr");
    const size_t blank = bytes.find("\n\n");
    ASSERT_NE(blank, std::string::npos);
    bytes.replace(blank, 2, std::string("\n\0 NUL-led line\n", 16));
    std::ofstream(dir / "nul.hdr", std::ios::binary) << bytes;
    expect_same_pixels(read_image(dir / "nul.hdr"), read_image(dir / "plain.hdr"));
    bytes.resize(bytes.size() - 20);
    std::ofstream(dir / "nul_cut.hdr", std::ios::binary) << bytes;
    expect_error([&] { read_image(dir / "nul_cut.hdr"); },
                 {"nul_cut.hdr", "the pixel data ends in scanline", "(truncated file)"});
}

// The image fuzzer's UB: stb memcpy'd a zero-length first IDAT to a null
// buffer. Empty IDAT chunks add nothing to the compressed stream: a file
// with them decodes as the file without.
TEST(ImagePng, EmptyIdatChunksDecodeAsTheFileWithout) {
    ScratchDir dir;
    write_png(ramp_image(9, 5), dir / "plain.png");
    std::string bytes = read_bytes(dir / "plain.png");
    const size_t idat = bytes.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    const std::string empty_idat("\0\0\0\0IDAT\x35\xaf\x06\x1e", 12);  // length 0, CRC
    bytes.insert(idat - 4, empty_idat);                                // before the first IDAT
    bytes.insert(bytes.find("IEND") - 4, empty_idat);                  // and after the last
    std::ofstream(dir / "empty_idat.png", std::ios::binary) << bytes;
    expect_same_pixels(read_image(dir / "empty_idat.png"), read_image(dir / "plain.png"));
    // Only empty IDATs: no image data, an error naming the file.
    const size_t first = bytes.find("IDAT", bytes.find("IDAT") + 4) - 4;
    size_t length = 0;
    for (int b = 0; b < 4; ++b) length = length << 8 | uint8_t(bytes[first + size_t(b)]);
    bytes.erase(first, 12 + length);
    std::ofstream(dir / "no_idat.png", std::ios::binary) << bytes;
    expect_error([&] { read_image(dir / "no_idat.png"); }, {"no_idat.png", "cannot read"});
}

// JPEG is read by libjpeg-turbo (image_jpeg.cpp). The inputs that broke
// stb's JPEG decoder, rebuilt from a valid file: a Huffman table declaring
// more than 256 codes is an error; bytes that only look like a DHT inside
// another segment (here an APP15 payload) are skipped with their segment; a
// scan decoding with an AC table no DHT segment defined decodes with T.81's
// standard table (K.3, what Motion-JPEG frames rely on), which is the table
// stb's writer used, so the pixels are unchanged.
TEST(ImageJpeg, HuffmanTablesOver256CodesAreErrorsAndMissingOnesAreTheStandardOnes) {
    ScratchDir dir;
    // A smooth ramp: red along x, green along y, blue constant.
    std::vector<uint8_t> rgb(3 * 16 * 8);
    for (size_t i = 0; i < rgb.size() / 3; ++i)
        rgb[3 * i] = uint8_t(i % 16 * 16), rgb[3 * i + 1] = uint8_t(i / 16 * 32),
                rgb[3 * i + 2] = 128;
    const std::string plain = (dir / "plain.jpg").string();
    ASSERT_TRUE(stbi_write_jpg(plain.c_str(), 16, 8, 3, rgb.data(), 95));
    const Image reference = read_image(plain);
    EXPECT_EQ(reference.width, 16);
    EXPECT_EQ(reference.height, 8);
    // Lossy, but close to what was written: at quality 95 stb writes 4:4:4
    // with quantisation steps of 1-3 codes (its tables scaled by 0.1), so a
    // smooth ramp comes back within a few codes (measured: mean 0.80, worst 3).
    double error = 0.0, worst = 0.0;
    for (size_t i = 0; i < rgb.size(); ++i) {
        const double e =
            std::abs(srgb_encode(reference.pixels[i / 3][int(i % 3)]) * 255.0 - rgb[i]);
        error += e, worst = std::max(worst, e);
    }
    EXPECT_LT(error / double(rgb.size()), 1.5);
    EXPECT_LE(worst, 4.0 + 1e-4);
    std::string bytes = read_bytes(plain);
    // An APP15 segment whose payload reads like a DHT with 16 x 255 codes.
    std::string app("\xff\xef\x00\x18\xff\xc4\x00\x13\x00", 9);
    app += std::string(16, '\xff');
    app.resize(2 + 0x18);
    std::string with_app = bytes;
    with_app.insert(2, app);
    std::ofstream(dir / "app.jpg", std::ios::binary) << with_app;
    expect_same_pixels(read_image(dir / "app.jpg"), reference);
    const size_t dht = bytes.find("\xff\xc4");
    ASSERT_NE(dht, std::string::npos);
    // The AC table of slot 0 moved to slot 2: the scan decodes with AC table
    // 0, which no DHT segment defines.
    {
        std::string moved = bytes;
        const size_t end =
            dht + 2 + (size_t(uint8_t(moved[dht + 2])) << 8 | uint8_t(moved[dht + 3]));
        bool found = false;
        for (size_t q = dht + 4; q + 17 <= end;) {
            size_t codes = 0;
            for (size_t i = 1; i <= 16; ++i) codes += uint8_t(moved[q + i]);
            if (moved[q] == '\x10') moved[q] = '\x12', found = true;
            q += 17 + codes;
        }
        ASSERT_TRUE(found) << "stb's writer puts AC table 0 in its first DHT segment";
        std::ofstream(dir / "no_ac0.jpg", std::ios::binary) << moved;
        expect_same_pixels(read_image(dir / "no_ac0.jpg"), reference);
    }
    // The first real DHT's first count raised to 255: 255 + the others > 256.
    bytes[dht + 5] = '\xff';
    bytes[dht + 6] = '\xff';
    std::ofstream(dir / "dht.jpg", std::ios::binary) << bytes;
    expect_error([&] { read_image(dir / "dht.jpg"); },
                 {"dht.jpg: cannot read JPEG file", "Huffman table", "libjpeg-turbo"});
}

// A JPEG written with libjpeg itself (stb writes baseline RGB and grey
// only): `components` 3 (RGB) or 4 (CMYK) of `pixels`, row-major;
// `progressive` with libjpeg's default progression (10 scans for colour).
std::string libjpeg_encode(int width, int height, int components,
                           const std::vector<unsigned char>& pixels, bool progressive,
                           const std::vector<jpeg_scan_info>& scans = {}) {
    jpeg_compress_struct cinfo;
    jpeg_error_mgr errors;
    cinfo.err = jpeg_std_error(&errors);
    jpeg_create_compress(&cinfo);
    unsigned char* out = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&cinfo, &out, &size);
    cinfo.image_width = JDIMENSION(width);
    cinfo.image_height = JDIMENSION(height);
    cinfo.input_components = components;
    cinfo.in_color_space = components == 4 ? JCS_CMYK : JCS_RGB;
    jpeg_set_defaults(&cinfo);
    jpeg_set_quality(&cinfo, 90, TRUE);
    if (progressive) jpeg_simple_progression(&cinfo);
    if (!scans.empty()) cinfo.scan_info = scans.data(), cinfo.num_scans = int(scans.size());
    jpeg_start_compress(&cinfo, TRUE);
    const size_t stride = size_t(width) * size_t(components);
    while (cinfo.next_scanline < cinfo.image_height) {
        JSAMPROW rows[1] = {const_cast<unsigned char*>(pixels.data()) +
                            stride * cinfo.next_scanline};
        jpeg_write_scanlines(&cinfo, rows, 1);
    }
    jpeg_finish_compress(&cinfo);
    jpeg_destroy_compress(&cinfo);
    std::string bytes(reinterpret_cast<const char*>(out), size);
    std::free(out);
    return bytes;
}

// Progressive coding reorders the same quantised coefficients (T.81 Annex
// G), so a progressive file decodes to exactly the pixels of the baseline
// file of the same quality; a file cut after its first scans is an error
// (libjpeg would show the coarse scans' image), not a blurry image. A valid
// progressive file of 568 scans (every AC coefficient of every component in
// its own band, sent in three bit-planes) is refused: above the 500-scan cap.
TEST(ImageJpeg, ProgressiveDecodesAsBaselineAndATruncatedOneIsAnError) {
    ScratchDir dir;
    const int w = 40, h = 24;
    std::vector<unsigned char> rgb(size_t(w * h * 3));
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t((i * 37 / 3) % 251);
    std::ofstream(dir / "baseline.jpg", std::ios::binary) << libjpeg_encode(w, h, 3, rgb, false);
    const std::string progressive = libjpeg_encode(w, h, 3, rgb, true);
    std::ofstream(dir / "progressive.jpg", std::ios::binary) << progressive;
    const Image baseline = read_image(dir / "baseline.jpg");
    ASSERT_EQ(baseline.width, w);
    ASSERT_EQ(baseline.height, h);
    expect_same_pixels(read_image(dir / "progressive.jpg"), baseline);
    std::ofstream(dir / "cut.jpg", std::ios::binary)
        << progressive.substr(0, progressive.size() / 2);
    expect_error([&] { read_image(dir / "cut.jpg"); }, {"cut.jpg: cannot read JPEG file"});
    std::vector<jpeg_scan_info> scans;
    scans.push_back({3, {0, 1, 2, 0}, 0, 0, 0, 0});  // DC of the 3 components
    for (int al : {2, 1, 0})  // first pass at bit 2, refinements at bits 1, 0
        for (int c = 0; c < 3; ++c)
            for (int k = 1; k < 64; ++k)
                scans.push_back({1, {c, 0, 0, 0}, k, k, al == 2 ? 0 : al + 1, al});
    ASSERT_EQ(scans.size(), 568u);
    std::ofstream(dir / "scans.jpg", std::ios::binary)
        << libjpeg_encode(w, h, 3, rgb, false, scans);
    expect_error([&] { read_image(dir / "scans.jpg"); },
                 {"scans.jpg: cannot read JPEG file: more than 500 scans"});
}

// Corrupt data that libjpeg would decode with grey rows (a warning) is an
// error, so is a CMYK file, and the size a header claims is checked before
// anything is decoded. A greyscale JPEG reads as grey RGB.
TEST(ImageJpeg, TruncatedCmykOversizedAreErrorsAndGreyIsRead) {
    ScratchDir dir;
    std::vector<uint8_t> grey(32 * 16);
    for (size_t i = 0; i < grey.size(); ++i) grey[i] = uint8_t(i % 32 * 8);
    const std::string path = (dir / "grey.jpg").string();
    ASSERT_TRUE(stbi_write_jpg(path.c_str(), 32, 16, 1, grey.data(), 95));
    const Image image = read_image(path);
    ASSERT_EQ(image.width, 32);
    for (const glm::vec3& p : image.pixels) {
        EXPECT_EQ(p.x, p.y);
        EXPECT_EQ(p.y, p.z);
    }
    const std::string bytes = read_bytes(path);
    // Cut in the middle of the entropy-coded data (before the EOI marker).
    std::ofstream(dir / "cut.jpg", std::ios::binary) << bytes.substr(0, bytes.size() - 40);
    expect_error([&] { read_image(dir / "cut.jpg"); },
                 {"cut.jpg: cannot read JPEG file", "Premature end of JPEG file"});
    // The frame header (SOF0: length, precision, height, width, components)
    // claims 60000 x 60000 pixels.
    std::string huge = bytes;
    const size_t sof = huge.find("\xff\xc0");
    ASSERT_NE(sof, std::string::npos);
    huge[sof + 5] = '\xea', huge[sof + 6] = '\x60';
    huge[sof + 7] = '\xea', huge[sof + 8] = '\x60';
    std::ofstream(dir / "huge.jpg", std::ios::binary) << huge;
    set_memory_limit(uint64_t(1) << 30);
    expect_error([&] { read_image(dir / "huge.jpg"); },
                 {"huge.jpg: reading the JPEG image needs about", "image 60000x60000"});
    set_memory_limit(std::nullopt);
    // A CMYK file (written by libjpeg itself) is refused by name.
    std::ofstream(dir / "cmyk.jpg", std::ios::binary)
        << libjpeg_encode(8, 8, 4, std::vector<unsigned char>(8 * 8 * 4, 100), false);
    expect_error([&] { read_image(dir / "cmyk.jpg"); },
                 {"cmyk.jpg: cannot read JPEG file: it is a CMYK image"});
}

TEST(ImageErrors, RejectsNonFinitePixelsOnReadWithCoordinates) {
    ScratchDir dir;
    // write_exr refuses NaN, so write the bad map with OpenEXR directly.
    Image image(6, 4, glm::vec3(1.0f));
    image.at(3, 2).y = std::nanf("");
    image.at(5, 3).x = INFINITY;
    {
        Imf::Header header(6, 4);
        Imf::FrameBuffer frame;
        const char* names[3] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c) {
            header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
            frame.insert(names[c],
                         Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&image.pixels[0][c]),
                                    sizeof(glm::vec3), 6 * sizeof(glm::vec3)));
        }
        Imf::OutputFile out((dir / "nan.exr").c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(4);
    }
    // The first offending pixel in scan order is reported.
    expect_error([&] { read_image(dir / "nan.exr"); }, {"nan.exr", "x=3, y=2", "non-finite"});
}

TEST(ImageErrors, WritersRefuseMissingDirectoryAndNonFinitePixels) {
    ScratchDir dir;
    const Image good(4, 4, glm::vec3(0.5f));
    for (const char* name : {"a.exr", "a.png", "a.hdr"}) {
        const auto path = dir / "no_such_dir" / name;
        expect_error([&] { write_image(good, path); }, {path.string(), "does not exist"});
    }
    Image bad = good;
    bad.at(1, 2).z = std::nanf("");
    for (const char* name : {"b.exr", "b.png", "b.hdr"}) {
        expect_error([&] { write_image(bad, dir / name); }, {name, "x=1, y=2", "non-finite"});
        EXPECT_FALSE(std::filesystem::exists(dir / name)) << "no partial file may be left";
    }
    expect_error([&] { write_image(good, dir / "c.bmp"); }, {"c.bmp", "unknown", ".png"});
    expect_error([&] { write_image(Image(), dir / "d.exr"); }, {"d.exr", "empty"});
}

// A full disk (here a file-size limit, SIGXFSZ ignored) left a truncated
// EXR, and stb's PNG writer reported success on a failed fwrite; a failed
// PNG left the EXR of the same render behind. Now a failed set changes no
// file: the old contents stay, and no temporary file is left.
TEST(ImageErrors, FailedWritesLeaveEveryFileAsItWas) {
    ScratchDir dir;
    const Image old_image(4, 4, glm::vec3(0.25f));
    write_image(old_image, dir / "x.exr");
    write_image(old_image, dir / "x.png");
    Image big(256, 256);
    for (size_t i = 0; i < big.pixels.size(); ++i)
        big.pixels[i] = glm::vec3(float(i % 251) / 251.0f, float(i % 241) / 241.0f, 0.5f);
    const auto count_files = [&] {
        int n = 0;
        for (const auto& e : std::filesystem::directory_iterator(dir / ""))
            n += e.is_regular_file();
        return n;
    };
    {
        struct rlimit saved {};
        ::getrlimit(RLIMIT_FSIZE, &saved);
        const auto previous = std::signal(SIGXFSZ, SIG_IGN);
        struct rlimit small = saved;
        small.rlim_cur = 4096;  // both encoded images are larger
        ::setrlimit(RLIMIT_FSIZE, &small);
        for (const char* name : {"x.exr", "x.png", "x.hdr"})
            EXPECT_THROW(write_image(big, dir / name), Error) << name;
        const Image other(4, 4, glm::vec3(0.75f));  // small: its own write succeeds
        EXPECT_THROW(write_images({{&other, dir / "x.exr"}, {&big, dir / "x.png"}}), Error);
        ::setrlimit(RLIMIT_FSIZE, &saved);
        std::signal(SIGXFSZ, previous);
    }
    EXPECT_EQ(count_files(), 2);
    EXPECT_EQ(read_image(dir / "x.exr").pixels, old_image.pixels);
    EXPECT_NEAR(read_image(dir / "x.png").pixels[0].x, 0.25f, 0.01f);
    // A directory where an output goes: refused before anything is written.
    std::filesystem::create_directory(dir / "d.png");
    expect_error(
        [&] {
            write_images({{&big, dir / "new.exr"}, {&big, dir / "d.png"}});
        },
        {"d.png", "is a directory"});
    EXPECT_FALSE(std::filesystem::exists(dir / "new.exr"));
    EXPECT_EQ(count_files(), 2);
}

}  // namespace
}  // namespace glintlab
