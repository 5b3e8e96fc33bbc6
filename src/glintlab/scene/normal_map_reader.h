// The "normal_map" key of a material (docs/SCENE_FORMAT.md, "Normal maps"):
// {"texture": "n.png", "scale", "encoding", "filtering", "mixture",
// "uv_transform", "wrap"}, a tangent-space map in glTF's convention (x along ∂p/∂u, y "up"
// in the image, z out of the surface; PNG/JPEG codes c hold 2c − 1).
#pragma once

#include <memory>

#include "glintlab/core/json_reader.h"
#include "glintlab/core/normal_map.h"
#include "glintlab/scene/texture_reader.h"

namespace glintlab {

// Reads the normal map at `key` of `material` (which must hold an object).
// Errors name the file, the JSON path, the texel and the allowed range.
std::shared_ptr<const NormalMap> read_normal_map(JsonObject& material, std::string_view key,
                                                 TextureFileCache& files);

}  // namespace glintlab
