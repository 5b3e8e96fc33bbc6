// Background: the environment (or black) seen along each camera ray through
// the pixel centre; scene/environment.cpp direction_to_uv and bilinear eval
// (texel centres at (i + 0.5) / W, u wraps, v clamps: GL_REPEAT /
// GL_CLAMP_TO_EDGE with GL_LINEAR and no mipmaps do the same).
#include "glintlab/core/constants.glsl"
in vec2 v_ndc;
out vec4 o_radiance;
uniform mat4 u_inverse_view_projection;
uniform bool u_orthographic;
uniform vec3 u_view_forward;
uniform bool u_has_environment;
uniform float u_environment_scale;
uniform float u_environment_rotation;  // radians about +y
layout(binding = 0) uniform sampler2D u_environment;
void main() {
    if (!u_has_environment) {
        o_radiance = vec4(0.0f, 0.0f, 0.0f, 1.0f);
        return;
    }
    vec4 a = u_inverse_view_projection * vec4(v_ndc, -1.0f, 1.0f);
    vec4 c = u_inverse_view_projection * vec4(v_ndc, 1.0f, 1.0f);
    vec3 d = u_orthographic ? u_view_forward : normalize(c.xyz / c.w - a.xyz / a.w);
    float theta = acos(clamp(d.y, -1.0f, 1.0f));
    float phi = atan(d.x, -d.z) - u_environment_rotation;
    float u = 0.5f + phi * INV_TWO_PI;
    u -= floor(u);
    vec3 env = textureLod(u_environment, vec2(u, theta * INV_PI), 0.0f).rgb;
    o_radiance = vec4(u_environment_scale * env, 1.0f);
}
