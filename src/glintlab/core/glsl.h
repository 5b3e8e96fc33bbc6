// GLSL compatibility layer: lets the shared `.glsl` shading sources compile as
// C++ (ARCHITECTURE.md §2). GLM mirrors GLSL's types and built-in functions;
// this header adds the few spellings GLSL has and C++ lacks.
//
// Rules for shared .glsl code (checked by the C++ compiler on one side and by
// glslangValidator on the other, see shader_glslang_test.cpp):
//  - no pointers, references, templates, recursion, STL, lambdas;
//  - `inout`/`out` parameters written INOUT(T) / OUT(T);
//  - float literals with an `f` suffix (2.0f): GLM refuses vec3 * double;
//  - no multi-component swizzles (`v.xy`): write vec2(v.x, v.y);
//  - no reserved words of either language as names (sample, filter, input,
//    output, and, or, not, this, new, delete, template, ...);
//  - include guards in every library file (stage files *.frag.glsl... are roots);
//  - textures and buffers reached only through fetch functions that each
//    back end defines.
//
// Including a shared file from C++:
//     namespace glintlab::shader {
//     #include "glintlab/microfacet/ndf.glsl"
//     }
// (see GLINTLAB_SHADER_BEGIN / END below).
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace glintlab::glsl {
using namespace glm;
using uint = unsigned int;
}  // namespace glintlab::glsl

#define INOUT(T) T&
#define OUT(T) T&
#define GLINTLAB_CPP 1

// Opens/closes the namespace into which shared .glsl files are included.
// Files that define only structs and constants use GLINTLAB_SHADER_BEGIN/END.
#define GLINTLAB_SHADER_BEGIN    \
    namespace glintlab::shader { \
    using namespace glintlab::glsl;
#define GLINTLAB_SHADER_END }

// Shared functions are plain (non-inline) definitions in GLSL; included from
// several C++ translation units they would collide at link time, so they go
// into an unnamed namespace (internal linkage) inside glintlab::shader.
// Unused ones would warn, hence the pragma.
#define GLINTLAB_SHADER_FUNCTIONS_BEGIN \
    GLINTLAB_SHADER_BEGIN               \
    _Pragma("GCC diagnostic push")      \
        _Pragma("GCC diagnostic ignored \"-Wunused-function\"") namespace {
#define GLINTLAB_SHADER_FUNCTIONS_END \
    }                                 \
    _Pragma("GCC diagnostic pop") GLINTLAB_SHADER_END
