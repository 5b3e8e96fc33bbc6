// The shared .glsl files, embedded at build time (cmake/EmbedShaders.cmake).
#pragma once

#include <span>
#include <string_view>

namespace glintlab {

struct ShaderSource {
    std::string_view path;  // relative to src/, e.g. "glintlab/core/hash.glsl"
    std::string_view text;
};

// Every shared .glsl file of the project, sorted by path.
std::span<const ShaderSource> shader_sources();

}  // namespace glintlab
