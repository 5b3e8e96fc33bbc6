// kneiphof2025.glsl compiled as C++ with fetch functions that read no map:
// for tests that call its counting functions directly (the fetch functions
// are never called there). Included once per test file, each its own copy
// in an anonymous namespace.
#pragma once

#include "glintlab/core/glsl.h"

GLINTLAB_SHADER_FUNCTIONS_BEGIN
vec3 kneiphof2025_radiance_fetch(vec3, float) {
    return vec3(0.0f);
}
vec4 kneiphof2025_weights_fetch(vec3, float, int) {
    return vec4(0.0f);
}
vec3 kneiphof2025_dfg_fetch(float, float) {
    return vec3(0.0f);
}
vec4 kneiphof2025_radiance_sources_fetch(vec3, float) {
    return vec4(0.0f);
}
int kneiphof2025_source_count() {
    return 0;
}
void kneiphof2025_source(int, vec3& d, vec3& p, float& r) {
    d = vec3(0.0f, 1.0f, 0.0f);
    p = vec3(0.0f);
    r = 0.0f;
}
vec3 kneiphof2025_sources_color() {
    return vec3(0.0f);
}
vec2 kneiphof2025_cone_jitter() {
    return vec2(0.5f);
}
#include "glintlab/glints/kneiphof2025/kneiphof2025.glsl"
GLINTLAB_SHADER_FUNCTIONS_END
