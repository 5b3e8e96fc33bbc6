// Radiance .hdr and PNG through stb_image / stb_image_write (JPEG: image_jpeg.cpp).
//
// Debian's libstb-dev also ships a compiled libstb.so, but the build links
// only what CMakeLists.txt names, so this file compiles the header-only
// implementations itself. They are made `static` (STB_*_STATIC) so they
// cannot clash with another translation unit that does the same.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "glintlab/core/error.h"
#include "glintlab/core/image_formats.h"

namespace glintlab::image_formats {
namespace {

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

[[noreturn]] void fail_decode(const std::filesystem::path& path, const char* format) {
    const char* reason = stbi_failure_reason();
    fail("{}: cannot read {} file: {}", path.string(), format, reason ? reason : "unknown error");
}

}  // namespace

namespace {

// Advances `pos` over one header line as stb_image's Radiance reader
// (stbi__hdr_gettoken) reads it, and returns the line's first character
// ('\0' for an empty line). stb ends the header at the first line whose
// first character is '\0' — an empty line, but also a line starting with
// a NUL byte or the end of the file — and a line longer than 1023 bytes is
// cut there and skipped to its newline. The pixel walk below must start
// where stb's decoder starts: a walker that looked for the first empty line
// instead let a header with a NUL-led line hide a truncated RLE scanline
// from the check, and stb then read zero run counts past the end of the
// file forever (libFuzzer's timeout; fuzz/regressions/image/
// hdr_nul_header_line_hang.hdr).
char stb_header_line(const std::string& bytes, size_t& pos) {
    const size_t n = bytes.size();
    auto get8 = [&]() -> char { return pos < n ? bytes[pos++] : '\0'; };
    std::string line;
    char c = get8();
    // stb tests for the end after reading: the file's last byte is dropped
    // from a line that has no newline.
    while (pos < n && c != '\n') {
        line.push_back(c);
        if (line.size() == 1023) {
            while (pos < n && get8() != '\n') {
            }
            break;
        }
        c = get8();
    }
    return line.empty() ? '\0' : line[0];
}

// stb_image's Radiance decoder loops forever on a run count of 0 in an RLE
// scanline, and 0 is what it reads past the end of the file (stbi__get8),
// so a truncated .hdr hung the reader (found by the image fuzzer); a flat
// (not run-length encoded) file that ends early decoded its missing pixels
// as black without a word. So the pixel data is walked first as stb decodes
// it: the header is read line by line exactly as stb tokenizes it (see
// stb_header_line), then widths in [8, 32768) are RLE scanlines "2 2 hi lo"
// (lo + 256 hi = width), then per channel runs: a count above 128 repeats
// the next byte count − 128 times, a count up to 128 is followed by that
// many bytes; other widths, or a scanline not starting with 2 2, are flat
// from there (4 bytes a pixel for the whole image, as stb restarts). A zero
// count or data ending before the last pixel is an error naming the file
// and the scanline; what stb itself rejects (wrong scanline length, runs
// past the width) is left to it.
void check_radiance_pixel_data(const std::string& bytes, int width, int height,
                               const std::filesystem::path& path) {
    size_t pos = 0;
    stb_header_line(bytes, pos);                   // "#?RADIANCE"
    while (stb_header_line(bytes, pos) != '\0') {  // header lines
    }
    stb_header_line(bytes, pos);  // "-Y height +X width"
    const size_t n = bytes.size();
    auto truncated = [&](int scanline) {
        fail(
            "{}: cannot read Radiance .hdr file: the pixel data ends in scanline {} of {} "
            "(truncated file)",
            path.string(), scanline, height);
    };
    auto byte = [&](int scanline) {
        if (pos >= n) truncated(scanline);
        return static_cast<unsigned>(static_cast<uint8_t>(bytes[pos++]));
    };
    const uint64_t flat_bytes = 4 * uint64_t(width) * uint64_t(height);
    if (width < 8 || width >= 32768) {
        if (n - pos < flat_bytes) truncated(int((n - pos) / 4 / uint64_t(width)));
        return;
    }
    for (int j = 0; j < height; ++j) {
        if (n - pos < 4) truncated(j);
        const unsigned c1 = uint8_t(bytes[pos]), c2 = uint8_t(bytes[pos + 1]),
                       hi = uint8_t(bytes[pos + 2]), lo = uint8_t(bytes[pos + 3]);
        if (c1 != 2 || c2 != 2 || (hi & 0x80)) {
            if (n - pos < flat_bytes) truncated(j);
            return;
        }
        pos += 4;
        if (int((hi << 8) | lo) != width) return;
        for (int channel = 0; channel < 4; ++channel) {
            for (int i = 0; i < width;) {
                unsigned count = byte(j);
                if (count > 128) {
                    byte(j);
                    count -= 128;
                } else {
                    if (count == 0)
                        fail(
                            "{}: cannot read Radiance .hdr file: a run of length 0 in scanline "
                            "{} (corrupt run-length data)",
                            path.string(), j);
                    if (n - pos < count) truncated(j);
                    pos += count;
                }
                if (count > unsigned(width - i)) return;
                i += int(count);
            }
        }
    }
}

// The bytes of a PNG file as stb_image may read them, after two checks of
// its chunks (big-endian length, type, data, CRC; PNG specification §5.3):
// - stb grows its compressed-data buffer to the length an IDAT chunk
//   declares before reading the chunk, so a 175-byte PNG declaring a 1 GB
//   IDAT allocated 1 GB (found by the image fuzzer): a declared length beyond
//   the end of the file is an error naming the file and the chunk.
// - stb copies an IDAT chunk's data to the end of its buffer with memcpy,
//   and before the first non-empty IDAT that buffer is a null pointer, so a
//   zero-length first IDAT was a memcpy to null (UB; found by the image
//   fuzzer, fuzz/regressions/image/png_empty_first_idat.png). An empty IDAT
//   adds nothing to the compressed stream (the stream is the concatenation
//   of the IDAT contents, §10.1), so empty IDAT chunks are dropped from the
//   bytes handed to stb: the decoded image is the same.
// Not a PNG: returned unchanged.
std::string png_bytes_for_stb(const std::string& bytes, const std::filesystem::path& path) {
    if (bytes.size() < 8 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return bytes;
    std::string kept = bytes.substr(0, 8);
    size_t pos = 8;
    while (bytes.size() - pos >= 8) {
        const size_t chunk_start = pos;
        uint32_t length = 0;
        for (int b = 0; b < 4; ++b) length = length << 8 | uint8_t(bytes[pos + b]);
        const std::string raw_type = bytes.substr(pos + 4, 4);
        std::string type = raw_type;
        for (char& c : type)
            if (!std::isalpha(static_cast<unsigned char>(c))) c = '?';
        pos += 8;
        if (length > bytes.size() - pos)
            fail(
                "{}: cannot read PNG file: chunk '{}' declares {} bytes but only {} bytes of the "
                "file follow it",
                path.string(), type, length, bytes.size() - pos);
        pos += length;
        pos += std::min<size_t>(4, bytes.size() - pos);  // CRC
        if (raw_type != "IDAT" || length != 0) kept.append(bytes, chunk_start, pos - chunk_start);
        if (raw_type == "IEND") return kept;
    }
    kept.append(bytes, pos, std::string::npos);  // a trailing fragment: stb reports it
    return kept;
}

}  // namespace

Image read_radiance_hdr(const std::filesystem::path& path) {
    const std::string bytes = read_file_bytes(path);
    const auto* p = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = static_cast<int>(bytes.size());
    // Checked before anything is decoded: given a file without the RGBE
    // header, stbi_loadf would run its other readers on it (those not
    // hardened: see require_png_or_jpeg_signature) and convert their output.
    if (!stbi_is_hdr_from_memory(p, size))
        fail(
            "{}: cannot read Radiance .hdr file: no RGBE header (the file does not start with "
            "#?RADIANCE or #?RGBE and a newline)",
            path.string());
    int w = 0, h = 0, channels_in_file = 0;
    if (!stbi_info_from_memory(p, size, &w, &h, &channels_in_file))
        fail_decode(path, "Radiance .hdr");
    // stb decodes into 3 floats a pixel (12 bytes) before the copy.
    require_image_memory(path, "Radiance .hdr image", w, h, 12);
    check_radiance_pixel_data(bytes, w, h, path);
    // Radiance RGBE is linear already; stbi_loadf applies no transfer curve to .hdr input.
    std::unique_ptr<float, StbFree> data(
        stbi_loadf_from_memory(p, size, &w, &h, &channels_in_file, 3));
    if (!data) fail_decode(path, "Radiance .hdr");
    Image image(w, h);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] =
            glm::vec3(data.get()[3 * i], data.get()[3 * i + 1], data.get()[3 * i + 2]);
    return image;
}

// stb guesses the format from the content and would parse any it knows
// (PNM, BMP, GIF, PSD, TGA, PIC besides PNG and JPEG) whatever the file is
// called. Those header readers are not hardened (the PNM one overflowed an
// int on a long width: fuzz/regressions/image/pnm_width_int_overflow.png),
// so only PNG reaches stb, and JPEG goes to libjpeg-turbo (image_jpeg.cpp),
// each told by its signature whatever the file's extension.
namespace {

// The file's bytes, told apart by their signature: a JPEG as read, a PNG as
// stb may read it (png_bytes_for_stb); anything else is an error.
struct PngOrJpeg {
    std::string bytes;
    bool jpeg = false;
};
PngOrJpeg png_or_jpeg_bytes(std::string file_bytes, const std::filesystem::path& path) {
    static constexpr std::string_view kPng("\x89PNG\r\n\x1a\n", 8);
    static constexpr std::string_view kJpeg("\xff\xd8\xff", 3);
    if (file_bytes.starts_with(kJpeg)) return {std::move(file_bytes), true};
    if (!file_bytes.starts_with(kPng))
        fail(
            "{}: cannot read PNG/JPEG file: it has neither the PNG signature nor the JPEG "
            "start-of-image marker (stb's other formats are not read)",
            path.string());
    return {png_bytes_for_stb(file_bytes, path), false};
}
PngOrJpeg png_or_jpeg_bytes(const std::filesystem::path& path) {
    return png_or_jpeg_bytes(read_file_bytes(path), path);
}

}  // namespace

Image read_srgb_8bit_or_16bit(const std::filesystem::path& path) {
    const PngOrJpeg file = png_or_jpeg_bytes(path);
    if (file.jpeg) return read_jpeg(file.bytes, path);
    const std::string& bytes = file.bytes;
    const auto* p = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = static_cast<int>(bytes.size());
    int w = 0, h = 0, channels_in_file = 0;
    // stbi_loadf would linearise with a pure 2.2 gamma; load the integer codes instead and
    // apply the exact sRGB curve. Grey and grey+alpha files are expanded to RGB by stb.
    // stb decodes into up to 3 x 16 bits a pixel (plus its own row buffers,
    // counted as as much again).
    if (stbi_info_from_memory(p, size, &w, &h, &channels_in_file))
        require_image_memory(path, "PNG image", w, h, 12);
    Image image;
    if (stbi_is_16_bit_from_memory(p, size)) {
        std::unique_ptr<stbi_us, StbFree> data(
            stbi_load_16_from_memory(p, size, &w, &h, &channels_in_file, 3));
        if (!data) fail_decode(path, "16-bit PNG");
        image = Image(w, h);
        for (size_t i = 0; i < 3 * image.pixels.size(); ++i)
            image.pixels[i / 3][int(i % 3)] = srgb_decode(float(data.get()[i]) / 65535.0f);
    } else {
        std::unique_ptr<stbi_uc, StbFree> data(
            stbi_load_from_memory(p, size, &w, &h, &channels_in_file, 3));
        if (!data) fail_decode(path, "PNG");
        image = Image(w, h);
        float table[256];  // 256 codes: decode each once
        for (int v = 0; v < 256; ++v) table[v] = srgb_decode(float(v) / 255.0f);
        for (size_t i = 0; i < 3 * image.pixels.size(); ++i)
            image.pixels[i / 3][int(i % 3)] = table[data.get()[i]];
    }
    return image;
}

TextureImage read_png_or_jpeg_codes(const std::filesystem::path& path) {
    return decode_png_or_jpeg_codes(read_file_bytes(path), path);
}

TextureImage decode_png_or_jpeg_codes(std::string bytes_in, const std::filesystem::path& path) {
    const PngOrJpeg file = png_or_jpeg_bytes(std::move(bytes_in), path);
    TextureImage t;
    t.codes = true;
    if (file.jpeg) {
        // libjpeg-turbo's reader decodes sRGB exactly; encoding again gives
        // the 8-bit codes back to within float rounding (JPEG has no alpha).
        const Image image = read_jpeg(file.bytes, path);
        t.width = image.width, t.height = image.height;
        t.texels.reserve(image.pixels.size());
        for (const glm::vec3& p : image.pixels)
            t.texels.emplace_back(std::clamp(srgb_encode(p.x), 0.0f, 1.0f),
                                  std::clamp(srgb_encode(p.y), 0.0f, 1.0f),
                                  std::clamp(srgb_encode(p.z), 0.0f, 1.0f), 1.0f);
        return t;
    }
    const std::string& bytes = file.bytes;
    const auto* p = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = static_cast<int>(bytes.size());
    int w = 0, h = 0, channels_in_file = 0;
    // 4 x 16 bits a pixel for stb, 16 bytes for the texels.
    if (stbi_info_from_memory(p, size, &w, &h, &channels_in_file))
        require_image_memory(path, "PNG texture", w, h, 24);
    auto fill = [&](const auto* data, float max_code) {
        t.width = w, t.height = h;
        t.texels.resize(size_t(w) * size_t(h));
        for (size_t i = 0; i < t.texels.size(); ++i)
            for (int c = 0; c < 4; ++c) t.texels[i][c] = float(data[4 * i + size_t(c)]) / max_code;
    };
    if (stbi_is_16_bit_from_memory(p, size)) {
        std::unique_ptr<stbi_us, StbFree> data(
            stbi_load_16_from_memory(p, size, &w, &h, &channels_in_file, 4));
        if (!data) fail_decode(path, "16-bit PNG");
        fill(data.get(), 65535.0f);
    } else {
        std::unique_ptr<stbi_uc, StbFree> data(
            stbi_load_from_memory(p, size, &w, &h, &channels_in_file, 4));
        if (!data) fail_decode(path, "PNG");
        fill(data.get(), 255.0f);
    }
    return t;
}

namespace {

void append_to_string(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
}

// stbi_write_png/hdr ignore fwrite's errors (a full disk left a truncated
// file and success): the encoded bytes are written here and checked.
void write_bytes(const std::string& bytes, const std::filesystem::path& file,
                 const std::filesystem::path& name, const char* format) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    if (!out)
        fail("{}: cannot write {} file (is the directory writable and the disk not full?)",
             name.string(), format);
}

}  // namespace

void write_png_8bit(const Image& image, const std::filesystem::path& file,
                    const std::filesystem::path& name, float exposure_stops) {
    const float scale = std::exp2(exposure_stops);
    std::vector<uint8_t> bytes(3 * image.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const float encoded = std::clamp(srgb_encode(image.pixels[i][c] * scale), 0.0f, 1.0f);
            bytes[3 * i + size_t(c)] = uint8_t(std::lround(encoded * 255.0f));
        }
    }
    std::string encoded;
    if (!stbi_write_png_to_func(append_to_string, &encoded, image.width, image.height, 3,
                                bytes.data(), 3 * image.width))
        fail("{}: cannot encode PNG", name.string());
    write_bytes(encoded, file, name, "PNG");
}

void write_radiance_hdr(const Image& image, const std::filesystem::path& file,
                        const std::filesystem::path& name) {
    std::vector<float> rgb(3 * image.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + size_t(c)] = std::max(image.pixels[i][c], 0.0f);
    std::string encoded;
    if (!stbi_write_hdr_to_func(append_to_string, &encoded, image.width, image.height, 3,
                                rgb.data()))
        fail("{}: cannot encode Radiance .hdr", name.string());
    write_bytes(encoded, file, name, "Radiance .hdr");
}

}  // namespace glintlab::image_formats
