// Shadow maps, vertex stage: depth of world-space vertices seen from a light
// (realtime/gpu_renderer.cpp; the fragment stage is depth_only.frag.glsl).
layout(location = 0) in vec3 a_position;
uniform mat4 u_light_view_projection;
void main() { gl_Position = u_light_view_projection * vec4(a_position, 1.0f); }
