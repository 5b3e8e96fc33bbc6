// Move-only owners of OpenGL object names (for the OpenGL code only: includes
// libepoxy). Each deletes its object with the matching glDelete* call.
#pragma once

#include <utility>

#include <epoxy/gl.h>

namespace glintlab::gl {

template <void (*Delete)(GLuint)>
class Handle {
  public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    GLuint get() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    GLuint release() { return std::exchange(id_, 0); }  // caller owns the object
    void reset() {
        if (id_ != 0) Delete(id_);
        id_ = 0;
    }

  private:
    GLuint id_ = 0;
};

inline void delete_buffer(GLuint id) {
    glDeleteBuffers(1, &id);
}
inline void delete_texture(GLuint id) {
    glDeleteTextures(1, &id);
}
inline void delete_framebuffer(GLuint id) {
    glDeleteFramebuffers(1, &id);
}
inline void delete_vertex_array(GLuint id) {
    glDeleteVertexArrays(1, &id);
}
inline void delete_query(GLuint id) {
    glDeleteQueries(1, &id);
}
inline void delete_program(GLuint id) {
    glDeleteProgram(id);
}
inline void delete_shader(GLuint id) {
    glDeleteShader(id);
}

using Buffer = Handle<delete_buffer>;
using Texture = Handle<delete_texture>;
using Framebuffer = Handle<delete_framebuffer>;
using VertexArray = Handle<delete_vertex_array>;
using Query = Handle<delete_query>;
using Program = Handle<delete_program>;
using Shader = Handle<delete_shader>;

inline Buffer make_buffer() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return Buffer(id);
}
inline Texture make_texture(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return Texture(id);
}
inline Framebuffer make_framebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return Framebuffer(id);
}
inline VertexArray make_vertex_array() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return VertexArray(id);
}
inline Query make_query(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return Query(id);
}

}  // namespace glintlab::gl
