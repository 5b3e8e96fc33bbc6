#include "glintlab/core/image.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include <fmt/format.h>
#include <unistd.h>

#include "glintlab/core/error.h"
#include "glintlab/core/image_formats.h"
#include "glintlab/core/memory_limit.h"
#include "glintlab/core/regular_file.h"

namespace glintlab {

Image::Image(int w, int h, glm::vec3 fill) : width(w), height(h) {
    if (w < 0 || h < 0) fail("Image size {}x{} is negative", w, h);
    pixels.assign(size_t(w) * size_t(h), fill);
}

float luminance(glm::vec3 rgb) {
    return 0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z;
}

// IEC 61966-2-1: linear segment below 0.0031308 (encoded 0.04045), 2.4 power above.
float srgb_encode(float linear) {
    if (linear <= 0.0031308f) return 12.92f * linear;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float encoded) {
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

namespace {

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// Reports the first non-finite pixel in scan order, so the user can find it.
void require_finite(const Image& image, const std::filesystem::path& path, const char* what) {
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3& p = image.at(x, y);
            if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) continue;
            fail("{}: {} non-finite pixel at (x={}, y={}): ({}, {}, {}); pixels must be finite",
                 path.string(), what, x, y, p.x, p.y, p.z);
        }
    }
}

// Writers must never leave a silently wrong file: check everything we can before opening it.
void check_writable(const Image& image, const std::filesystem::path& path) {
    if (image.width <= 0 || image.height <= 0)
        fail("{}: cannot write an empty image ({}x{})", path.string(), image.width, image.height);
    if (image.pixels.size() != size_t(image.width) * size_t(image.height))
        fail("{}: image holds {} pixels but claims {}x{}", path.string(), image.pixels.size(),
             image.width, image.height);
    const std::filesystem::path parent = path.parent_path();
    std::error_code ec;
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
        fail("{}: cannot write, directory '{}' does not exist", path.string(), parent.string());
    require_finite(image, path, "cannot write image with a");
}

}  // namespace

void read_image_checks(const std::filesystem::path& path) {
    std::error_code ec;
    if (const std::string problem = regular_file_problem(path); !problem.empty())
        fail("{}: the image file {}", path.string(), problem);
    if (std::filesystem::file_size(path, ec) == 0) fail("{}: image file is empty", path.string());
}

Image read_image(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    const bool known =
        ext == ".exr" || ext == ".hdr" || ext == ".png" || ext == ".jpg" || ext == ".jpeg";
    if (!known)
        fail("{}: unknown image extension '{}' (allowed: .exr, .hdr, .png, .jpg, .jpeg)",
             path.string(), ext);
    read_image_checks(path);

    Image image;
    if (ext == ".exr")
        image = image_formats::read_exr(path);
    else if (ext == ".hdr")
        image = image_formats::read_radiance_hdr(path);
    else
        image = image_formats::read_srgb_8bit_or_16bit(path);

    if (image.width <= 0 || image.height <= 0)
        fail("{}: image has zero size ({}x{})", path.string(), image.width, image.height);
    require_finite(image, path, "input image has a");
    return image;
}

void write_images(const std::vector<ImageOutput>& outputs) {
    // Every output is written to a temporary file beside it, and only once
    // all are complete are they renamed over their paths: a full disk or a
    // failed write leaves no truncated file and no half of a set (an EXR
    // without its PNG); a rename within a directory is atomic.
    struct Staged {
        std::filesystem::path temp;
        bool done = false;
        ~Staged() {
            std::error_code ec;
            if (!done && !temp.empty()) std::filesystem::remove(temp, ec);
        }
    };
    static std::atomic<uint64_t> counter{0};
    std::vector<Staged> staged(outputs.size());
    for (size_t i = 0; i < outputs.size(); ++i) {
        const ImageOutput& o = outputs[i];
        const std::string ext = lower_extension(o.path);
        if (ext != ".exr" && ext != ".hdr" && ext != ".png")
            fail("{}: unknown output image extension '{}' (allowed: .exr, .hdr, .png)",
                 o.path.string(), ext);
        if (ext == ".png" && !std::isfinite(o.exposure_stops))
            fail("{}: exposure {} stops is not finite", o.path.string(), o.exposure_stops);
        check_writable(*o.image, o.path);
        // Checked before anything is written, so that the renames below
        // cannot fail half-way through the set.
        std::error_code ec;
        if (std::filesystem::exists(o.path, ec) && !std::filesystem::is_regular_file(o.path, ec))
            fail("{}: cannot write the image: the path {}", o.path.string(),
                 regular_file_problem(o.path));
        staged[i].temp =
            o.path.parent_path() /
            fmt::format(".{}.{}.{}.tmp", o.path.filename().string(), ::getpid(), counter++);
        if (ext == ".exr")
            image_formats::write_exr_zip_float(*o.image, staged[i].temp, o.path);
        else if (ext == ".hdr")
            image_formats::write_radiance_hdr(*o.image, staged[i].temp, o.path);
        else
            image_formats::write_png_8bit(*o.image, staged[i].temp, o.path, o.exposure_stops);
    }
    for (size_t i = 0; i < outputs.size(); ++i) {
        std::error_code ec;
        std::filesystem::rename(staged[i].temp, outputs[i].path, ec);
        if (ec)
            fail("{}: cannot replace the file with the written image: {}", outputs[i].path.string(),
                 ec.message());
        staged[i].done = true;
    }
}

void write_exr(const Image& image, const std::filesystem::path& path) {
    if (lower_extension(path) != ".exr") fail("{}: write_exr needs a .exr path", path.string());
    write_images({{&image, path}});
}

void write_png(const Image& image, const std::filesystem::path& path, float exposure_stops) {
    if (lower_extension(path) != ".png") fail("{}: write_png needs a .png path", path.string());
    write_images({{&image, path, exposure_stops}});
}

void write_hdr(const Image& image, const std::filesystem::path& path) {
    if (lower_extension(path) != ".hdr") fail("{}: write_hdr needs a .hdr path", path.string());
    write_images({{&image, path}});
}

void write_image(const Image& image, const std::filesystem::path& path, float exposure_stops) {
    write_images({{&image, path, exposure_stops}});
}

namespace image_formats {

void require_image_memory(const std::filesystem::path& path, const char* what, int64_t width,
                          int64_t height, uint64_t decode_bytes_per_pixel) {
    constexpr int64_t kMaxSide = (int64_t(1) << 31) - 1;
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
        fail("{}: {} claims a size of {}x{} pixels; each side must be in [1, {}]", path.string(),
             what, width, height, kMaxSide);
    const uint64_t pixels = uint64_t(width) * uint64_t(height);
    require_memory({{fmt::format("image {}x{}", width, height), pixels * sizeof(glm::vec3)},
                    {"decoder buffers", pixels * decode_bytes_per_pixel}},
                   fmt::format("{}: reading the {}", path.string(), what));
}

std::string read_file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("{}: cannot open image file", path.string());
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() > size_t(std::numeric_limits<int>::max()))
        fail("{}: image file too large (over 2 GiB)", path.string());
    return bytes;
}

}  // namespace image_formats

}  // namespace glintlab
