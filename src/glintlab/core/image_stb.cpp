// Radiance .hdr and PNG/JPEG through stb_image / stb_image_write.
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
#include <cmath>
#include <cstdint>
#include <memory>
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

Image read_radiance_hdr(const std::filesystem::path& path) {
    int w = 0, h = 0, channels_in_file = 0;
    // stb decodes into 3 floats a pixel (12 bytes) before the copy.
    if (stbi_info(path.string().c_str(), &w, &h, &channels_in_file))
        require_image_memory(path, "Radiance .hdr image", w, h, 12);
    // Radiance RGBE is linear already; stbi_loadf applies no transfer curve to .hdr input.
    std::unique_ptr<float, StbFree> data(
        stbi_loadf(path.string().c_str(), &w, &h, &channels_in_file, 3));
    if (!data) fail_decode(path, "Radiance .hdr");
    // stb would silently accept an 8-bit image here and invent a gamma for it.
    if (!stbi_is_hdr(path.string().c_str()))
        fail("{}: not a Radiance .hdr file (no RGBE header)", path.string());
    Image image(w, h);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] =
            glm::vec3(data.get()[3 * i], data.get()[3 * i + 1], data.get()[3 * i + 2]);
    return image;
}

Image read_srgb_8bit_or_16bit(const std::filesystem::path& path) {
    const std::string name = path.string();
    int w = 0, h = 0, channels_in_file = 0;
    // stbi_loadf would linearise with a pure 2.2 gamma; load the integer codes instead and
    // apply the exact sRGB curve. Grey and grey+alpha files are expanded to RGB by stb.
    // stb decodes into up to 3 x 16 bits a pixel (plus its own row buffers,
    // counted as as much again).
    if (stbi_info(name.c_str(), &w, &h, &channels_in_file))
        require_image_memory(path, "PNG/JPEG image", w, h, 12);
    Image image;
    if (stbi_is_16_bit(name.c_str())) {
        std::unique_ptr<stbi_us, StbFree> data(
            stbi_load_16(name.c_str(), &w, &h, &channels_in_file, 3));
        if (!data) fail_decode(path, "16-bit PNG");
        image = Image(w, h);
        for (size_t i = 0; i < 3 * image.pixels.size(); ++i)
            image.pixels[i / 3][int(i % 3)] = srgb_decode(float(data.get()[i]) / 65535.0f);
    } else {
        std::unique_ptr<stbi_uc, StbFree> data(
            stbi_load(name.c_str(), &w, &h, &channels_in_file, 3));
        if (!data) fail_decode(path, "PNG/JPEG");
        image = Image(w, h);
        float table[256];  // 256 codes: decode each once
        for (int v = 0; v < 256; ++v) table[v] = srgb_decode(float(v) / 255.0f);
        for (size_t i = 0; i < 3 * image.pixels.size(); ++i)
            image.pixels[i / 3][int(i % 3)] = table[data.get()[i]];
    }
    return image;
}

void write_png_8bit(const Image& image, const std::filesystem::path& path, float exposure_stops) {
    const float scale = std::exp2(exposure_stops);
    std::vector<uint8_t> bytes(3 * image.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const float encoded = std::clamp(srgb_encode(image.pixels[i][c] * scale), 0.0f, 1.0f);
            bytes[3 * i + size_t(c)] = uint8_t(std::lround(encoded * 255.0f));
        }
    }
    if (!stbi_write_png(path.string().c_str(), image.width, image.height, 3, bytes.data(),
                        3 * image.width))
        fail("{}: cannot write PNG file (is the directory writable and the disk not full?)",
             path.string());
}

void write_radiance_hdr(const Image& image, const std::filesystem::path& path) {
    std::vector<float> rgb(3 * image.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + size_t(c)] = std::max(image.pixels[i][c], 0.0f);
    if (!stbi_write_hdr(path.string().c_str(), image.width, image.height, 3, rgb.data()))
        fail(
            "{}: cannot write Radiance .hdr file (is the directory writable and the disk not "
            "full?)",
            path.string());
}

}  // namespace glintlab::image_formats
