// Bloom, pass 1: the bright part of the image above u_threshold, by
// core/image.cpp luminance (BT.709 Y).
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_in;
layout(rgba32f, binding = 1) uniform writeonly image2D u_bright;
uniform float u_threshold;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_in)))) return;
    vec3 c = imageLoad(u_in, p).rgb;
    float y = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
    vec3 b = y > u_threshold ? c * ((y - u_threshold) / y) : vec3(0.0f);
    imageStore(u_bright, p, vec4(b, 0.0f));
}
