#include "glintlab/gl/gl_program.h"

#include <vector>

#include "glintlab/core/error.h"
#include "glintlab/gl/gl_handles.h"

namespace glintlab::gl {
namespace {

std::string shader_log(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return std::string(log.data());
}

std::string program_log(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return std::string(log.data());
}

Shader compile(GLenum stage, const AssembledShader& source, const std::string& what) {
    Shader shader(glCreateShader(stage));
    const char* text = source.text.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint ok = 0;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (!ok)
        fail("{}: {} shader does not compile:\n{}", what,
             stage == GL_VERTEX_SHADER    ? "vertex"
             : stage == GL_COMPUTE_SHADER ? "compute"
                                          : "fragment",
             map_shader_log(source, shader_log(shader.get())));
    return shader;
}

}  // namespace

unsigned link_program(const AssembledShader& vertex, const AssembledShader& fragment,
                      const std::string& what) {
    const Shader vs = compile(GL_VERTEX_SHADER, vertex, what);
    const Shader fs = compile(GL_FRAGMENT_SHADER, fragment, what);
    Program program(glCreateProgram());
    glAttachShader(program.get(), vs.get());
    glAttachShader(program.get(), fs.get());
    glLinkProgram(program.get());
    GLint ok = 0;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok)
        fail("{}: the program does not link:\n{}", what,
             map_shader_log(fragment, program_log(program.get())));
    glDetachShader(program.get(), vs.get());
    glDetachShader(program.get(), fs.get());
    return program.release();
}

unsigned link_compute_program(const AssembledShader& compute, const std::string& what) {
    const Shader cs = compile(GL_COMPUTE_SHADER, compute, what);
    Program program(glCreateProgram());
    glAttachShader(program.get(), cs.get());
    glLinkProgram(program.get());
    GLint ok = 0;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok)
        fail("{}: the program does not link:\n{}", what,
             map_shader_log(compute, program_log(program.get())));
    glDetachShader(program.get(), cs.get());
    return program.release();
}

}  // namespace glintlab::gl
