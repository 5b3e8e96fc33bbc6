// Forward pass, vertex stage: world-space vertices (the scene's meshes are
// stored in world space; spheres are tessellated in world space on upload).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_dpdu;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_dpdu;
void main() {
    v_position = a_position;
    v_normal = a_normal;
    v_uv = a_uv;
    v_dpdu = a_dpdu;
    gl_Position = u_view_projection * vec4(a_position, 1.0f);
}
