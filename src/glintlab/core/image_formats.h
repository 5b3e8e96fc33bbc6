// Per-format readers and writers behind read_image / write_image (image.h).
// Internal to the image module: callers use image.h, which validates paths
// and pixels before and after these run.
#pragma once

#include <filesystem>

#include "glintlab/core/image.h"

namespace glintlab::image_formats {

// OpenEXR (image_exr.cpp).
Image read_exr(const std::filesystem::path& path);
void write_exr_zip_float(const Image& image, const std::filesystem::path& path);

// stb_image / stb_image_write (image_stb.cpp).
Image read_radiance_hdr(const std::filesystem::path& path);
Image read_srgb_8bit_or_16bit(const std::filesystem::path& path);  // PNG, JPEG
void write_png_8bit(const Image& image, const std::filesystem::path& path, float exposure_stops);
void write_radiance_hdr(const Image& image, const std::filesystem::path& path);

}  // namespace glintlab::image_formats
