// The texture form of a material parameter (docs/SCENE_FORMAT.md,
// "Textures"): {"texture": "f.png", "channel", "colorspace", "scale",
// "offset", "uv_transform", "wrap"} in place of a number or a colour.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string_view>

#include "glintlab/core/json_reader.h"
#include "glintlab/core/texture_image.h"
#include "glintlab/core/texture_input.h"

namespace glintlab {

// How a parameter's values are checked, filtered and stored.
struct TextureParameter {
    bool colour = false;          // RGB (albedo, tint); else one value a texel
    double min = 0.0, max = 1.0;  // the documented range of the parameter's value
    // Values in [0, min) are clamped to `min` with one warning that counts
    // them (a roughness of 0 in an 8-bit map); a negative value is no such
    // convention, so it is an error, as is any other value outside.
    bool clamp_below = false;
    // The quantity the mip chain and the footprint filter average, of the
    // value v: v itself, v² (a roughness α: its slope variance is what a
    // footprint's mixture of NDFs keeps, LEAN mapping) or e^v (ln N: the
    // expected facet count over a footprint is the integral of N).
    enum class Filtered { Value, Square, Exp } filtered = Filtered::Value;
};

// The files a scene's textures read, each decoded once; also the textures a
// caller hands over in memory under names starting with kArrayPrefix
// ("<array 0>": the Python module's NumPy arrays), which a scene's
// "texture" value names in place of a file.
using TextureFileCache = std::map<std::filesystem::path, std::shared_ptr<const TextureImage>>;
inline constexpr std::string_view kArrayPrefix = "<array ";
// Every in-memory name starts with it (arrays; a glTF file's embedded images).
inline constexpr std::string_view kInMemoryPrefix = "<";

// The image a texture block's "texture" names: a file (decoded once) or an
// array handed over in memory.
struct TextureSource {
    std::filesystem::path file;
    std::shared_ptr<const TextureImage> image;
};
TextureSource read_texture_source(JsonObject& block, TextureFileCache& files);
// The block's "uv_transform" (KHR_texture_transform's keys) and "wrap" (a
// mode for both axes, or [along u, along v]).
TextureUvTransform read_uv_transform(JsonObject& block);
TextureWraps read_texture_wrap(JsonObject& block);

// True when `key` holds an object (the texture form) rather than a number or colour.
bool is_texture_form(JsonObject& o, std::string_view key);

// Reads the texture form at `key` of `o` (which must hold one). Errors name
// the file, the JSON path and the allowed values.
std::shared_ptr<const TextureInput> read_texture_input(JsonObject& o, std::string_view key,
                                                       const TextureParameter& parameter,
                                                       TextureFileCache& files);
// The same for a texture form that is itself the JSON value `block` (an
// element of an array: "roughness": [{"texture": ...}, 0.2]).
std::shared_ptr<const TextureInput> read_texture_block(JsonObject& block,
                                                       const TextureParameter& parameter,
                                                       TextureFileCache& files);

}  // namespace glintlab
