// Bloom, pass 3: out = image + strength (glow - bright).
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_in;
layout(rgba32f, binding = 1) uniform readonly image2D u_bright;
layout(rgba32f, binding = 2) uniform readonly image2D u_glow;
layout(rgba32f, binding = 3) uniform writeonly image2D u_result;
uniform float u_strength;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_in)))) return;
    vec3 c = imageLoad(u_in, p).rgb + u_strength * (imageLoad(u_glow, p).rgb - imageLoad(u_bright, p).rgb);
    imageStore(u_result, p, vec4(c, 1.0f));
}
