// Shader assembly (Filament style): resolves `#include "glintlab/..."` lines
// of the embedded .glsl sources, each file once, and emits `#line N K`
// directives so a driver's error "K:N" maps back to file K of the assembled
// list (AssembledShader::files) and its line N.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace glintlab {

struct AssembledShader {
    std::string text;                // GLSL text ready for the driver
    std::vector<std::string> files;  // source-string number K -> file path
};

// The prelude every shared file expects on the GLSL side: version line and
// the INOUT/OUT macros of core/glsl.h.
std::string glsl_prelude(std::string_view version = "450 core");

// Assembles `root` (a path among shader_sources(), or inline text when
// `root_is_text`) with its includes. Throws glintlab::Error on a missing include.
AssembledShader assemble_shader(std::string_view root, bool root_is_text = false,
                                std::string_view prelude = {});

// Rewrites "K:N" / "K(N)" locations in a driver or glslang log into
// "path:N" using the file table of an assembled shader.
std::string map_shader_log(const AssembledShader& shader, std::string_view log);

}  // namespace glintlab
