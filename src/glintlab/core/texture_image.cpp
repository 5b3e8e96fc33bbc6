#include "glintlab/core/texture_image.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/image_formats.h"

namespace glintlab {

bool TextureImage::grey() const {
    return std::all_of(texels.begin(), texels.end(),
                       [](const glm::vec4& t) { return t.x == t.y && t.y == t.z; });
}

TextureImage read_texture_image(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    if (ext != ".png" && ext != ".jpg" && ext != ".jpeg") {
        // EXR and HDR hold linear values: read_image's are the texels.
        const Image image = read_image(path);
        TextureImage t;
        t.width = image.width, t.height = image.height;
        t.texels.reserve(image.pixels.size());
        for (const glm::vec3& p : image.pixels) t.texels.emplace_back(p, 1.0f);
        return t;
    }
    read_image_checks(path);
    TextureImage t = image_formats::read_png_or_jpeg_codes(path);
    if (t.width <= 0 || t.height <= 0)
        fail("{}: image has zero size ({}x{})", path.string(), t.width, t.height);
    return t;
}

TextureImage decode_texture_image(std::string bytes, const std::string& name) {
    if (bytes.empty()) fail("{}: the image is empty", name);
    TextureImage t = image_formats::decode_png_or_jpeg_codes(std::move(bytes), name);
    if (t.width <= 0 || t.height <= 0)
        fail("{}: image has zero size ({}x{})", name, t.width, t.height);
    return t;
}

}  // namespace glintlab
