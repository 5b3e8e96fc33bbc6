// The texels of an image file as a material texture reads them: all four
// channels, and for PNG/JPEG the stored codes (not decoded: whether they are
// sRGB-encoded colour or linear data is the material input's decision,
// scene/texture_reader.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

namespace glintlab {

struct TextureImage {
    int width = 0, height = 0;
    // Row-major from the top row. PNG/JPEG: code / maximum code in [0, 1]
    // (grey files repeat the grey in r, g and b; alpha 1 where the file has
    // none). EXR/HDR: linear RGB, alpha 1.
    std::vector<glm::vec4> texels;
    bool codes = false;  // PNG/JPEG: texels are stored codes (sRGB or linear: the reader decides)
    bool grey() const;   // every texel has r == g == b
};

// .png, .jpg/.jpeg, .exr, .hdr through the hardened readers of image.h (the
// same checks: existence, size limits, corrupt data, NaN/Inf texels), errors
// naming the file.
TextureImage read_texture_image(const std::filesystem::path& path);
// A PNG or JPEG image held in memory (a glTF file's embedded image), with
// the same checks; `name` names it in messages.
TextureImage decode_texture_image(std::string bytes, const std::string& name);

}  // namespace glintlab
