// In-memory image type and file I/O (OpenEXR, Radiance .hdr, PNG/JPEG).
//
// Every image in glintlab is linear Rec.709 RGB. Readers decode the file's
// transfer function (sRGB for PNG/JPEG) so callers never see encoded values;
// writers encode again where the format needs it.
#pragma once

#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

namespace glintlab {

// Linear Rec.709 RGB working space, row-major, (0,0) = top-left.
struct Image {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels;

    Image() = default;
    Image(int w, int h, glm::vec3 fill = glm::vec3(0));

    glm::vec3& at(int x, int y) { return pixels[index(x, y)]; }
    const glm::vec3& at(int x, int y) const { return pixels[index(x, y)]; }

  private:
    size_t index(int x, int y) const { return size_t(y) * size_t(width) + size_t(x); }
};

// Relative luminance Y of linear Rec.709 / sRGB-primaries RGB (ITU-R BT.709
// weights, the Y row of the RGB->XYZ matrix for D65 white).
float luminance(glm::vec3 rgb);

// IEC 61966-2-1 sRGB transfer curves (piecewise: linear toe, 2.4 power).
// Inputs outside [0,1] follow the same formulas (negative values stay on the
// linear toe); callers clamp where the format needs it.
float srgb_encode(float linear);
float srgb_decode(float encoded);

// Reads by extension (case-insensitive): .exr, .hdr, .png/.jpg/.jpeg.
// Throws glintlab::Error naming the file for a missing, unreadable or empty
// file, an unknown extension, or a NaN/Inf pixel (with its coordinates).
Image read_image(const std::filesystem::path& path);
// The checks read_image makes before decoding: the path names a readable,
// regular, non-empty file (errors name it).
void read_image_checks(const std::filesystem::path& path);

// Float32 RGB, ZIP compression.
void write_exr(const Image& image, const std::filesystem::path& path);
// 8-bit sRGB: scale by 2^exposure_stops, sRGB-encode, clamp to [0,1], round.
void write_png(const Image& image, const std::filesystem::path& path, float exposure_stops = 0.0f);
// Radiance RGBE (negative components are stored as 0: RGBE has no sign).
void write_hdr(const Image& image, const std::filesystem::path& path);
// Dispatches on the extension: .exr, .hdr, .png (exposure applies to .png only).
void write_image(const Image& image, const std::filesystem::path& path,
                 float exposure_stops = 0.0f);

// Several outputs written together (as write_image each): each to a temporary
// file beside its path, then all renamed over their paths, so a failure (a
// full disk, an unwritable file) leaves every path as it was. Every writer
// above goes through it.
struct ImageOutput {
    const Image* image;
    std::filesystem::path path;
    float exposure_stops = 0.0f;
};
void write_images(const std::vector<ImageOutput>& outputs);

}  // namespace glintlab
