// Linking GLSL programs from assembled shaders (core/shader_assembly.h):
// compile and link errors become glintlab::Error messages whose locations
// name the shared .glsl file and line (map_shader_log), not "0:123".
#pragma once

#include <string>

#include "glintlab/core/shader_assembly.h"

namespace glintlab::gl {

// Returns the program name (caller owns it: glDeleteProgram / gl::Program).
// `what` names the program in error messages, e.g. "forward[deliot2023, 1 point]".
unsigned link_program(const AssembledShader& vertex, const AssembledShader& fragment,
                      const std::string& what);
// The same for one compute shader.
unsigned link_compute_program(const AssembledShader& compute, const std::string& what);

}  // namespace glintlab::gl
