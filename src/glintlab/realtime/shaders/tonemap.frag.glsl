// Full-screen tonemap of the viewer: 2^exposure, sRGB encode, clamp (the
// convention of core/image.h write_png).
in vec2 v_ndc;
out vec4 o_color;
layout(binding = 0) uniform sampler2D u_hdr;
uniform float u_exposure_scale;  // 2^stops
// core/image.cpp srgb_encode (IEC 61966-2-1).
float srgb_encode(float x) {
    return x <= 0.0031308f ? 12.92f * x : 1.055f * pow(x, 1.0f / 2.4f) - 0.055f;
}
void main() {
    vec3 c = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb * u_exposure_scale;
    o_color = vec4(clamp(srgb_encode(c.r), 0.0f, 1.0f), clamp(srgb_encode(c.g), 0.0f, 1.0f),
                   clamp(srgb_encode(c.b), 0.0f, 1.0f), 1.0f);
}
