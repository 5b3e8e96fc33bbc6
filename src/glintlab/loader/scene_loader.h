// Reads a JSON scene file (docs/SCENE_FORMAT.md) strictly: unknown keys,
// wrong types, out-of-range values and missing files are errors that name the
// file, the JSON path and the allowed range.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "glintlab/scene/scene.h"
#include "glintlab/scene/texture_reader.h"

namespace glintlab {

Scene load_scene(const std::filesystem::path& file);
// Parses an already-read document; `file` names it in messages and anchors relative paths.
Scene parse_scene(const nlohmann::json& document, const std::filesystem::path& file);
// The same with textures handed over in memory (scene/texture_reader.h
// kArrayPrefix: a "texture" value "<array N>" names arrays["<array N>"]).
Scene parse_scene(const nlohmann::json& document, const std::filesystem::path& file,
                  TextureFileCache arrays);

}  // namespace glintlab
