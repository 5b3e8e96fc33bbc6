// Per-format readers and writers behind read_image / write_image (image.h).
// Internal to the image module: callers use image.h, which validates paths
// and pixels before and after these run.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "glintlab/core/image.h"
#include "glintlab/core/texture_image.h"

namespace glintlab::image_formats {

// Before a reader allocates an image of the size a file's header claims:
// an Image of width x height (12 bytes a pixel) plus `decode_bytes_per_pixel`
// of the decoder's own buffers must fit the memory limit
// (core/memory_limit.h), and both sides must be in [1, 2^31). A file of a
// few bytes can claim 2^31 x 2^31 pixels; this is an error naming the file
// and its size instead of an allocation that exhausts the machine.
void require_image_memory(const std::filesystem::path& path, const char* what, int64_t width,
                          int64_t height, uint64_t decode_bytes_per_pixel);

// OpenEXR (image_exr.cpp).
Image read_exr(const std::filesystem::path& path);
// Writers: `file` is written, `name` is the path messages give (the output
// the file is staged for, image.cpp).
void write_exr_zip_float(const Image& image, const std::filesystem::path& file,
                         const std::filesystem::path& name);

// The whole file (read_image has checked it exists and is not empty).
std::string read_file_bytes(const std::filesystem::path& path);

// stb_image / stb_image_write (image_stb.cpp).
Image read_radiance_hdr(const std::filesystem::path& path);
// PNG through stb, JPEG through read_jpeg, told apart by their signatures.
Image read_srgb_8bit_or_16bit(const std::filesystem::path& path);
// PNG (8 or 16 bits, 1-4 channels) or JPEG as stored codes / maximum code,
// RGBA (texture_image.h).
TextureImage read_png_or_jpeg_codes(const std::filesystem::path& path);
// The same from the bytes of an image held in memory; `path` names it in messages.
TextureImage decode_png_or_jpeg_codes(std::string bytes, const std::filesystem::path& path);
void write_png_8bit(const Image& image, const std::filesystem::path& file,
                    const std::filesystem::path& name, float exposure_stops);
void write_radiance_hdr(const Image& image, const std::filesystem::path& file,
                        const std::filesystem::path& name);

// JPEG through libjpeg-turbo (image_jpeg.cpp): `bytes` is the file at `path`.
Image read_jpeg(const std::string& bytes, const std::filesystem::path& path);

}  // namespace glintlab::image_formats
