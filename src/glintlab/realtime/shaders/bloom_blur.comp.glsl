// Bloom, pass 2: one axis of core/bloom_blur.cpp gaussian_blur_conserving:
// each source pixel is scaled by 1 / (its taps inside the image), then
// convolved. u_axis = 0: rows (x), 1: columns (y). Accumulates
// u_weight * result into u_out when u_accumulate.
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_src;
layout(rgba32f, binding = 1) uniform image2D u_out;
layout(std430, binding = 0) readonly buffer Taps { float u_taps[]; };
layout(std430, binding = 1) readonly buffer Scales { float u_scales[]; };
uniform int u_radius;
uniform int u_axis;
uniform bool u_accumulate;
uniform float u_weight;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_src);
    if (any(greaterThanEqual(p, size))) return;
    int n = u_axis == 0 ? size.x : size.y;
    int i = u_axis == 0 ? p.x : p.y;
    vec3 sum = vec3(0.0f);
    for (int k = -u_radius; k <= u_radius; ++k) {
        int s = i - k;  // source index; tap k
        if (s < 0 || s >= n) continue;
        ivec2 q = u_axis == 0 ? ivec2(s, p.y) : ivec2(p.x, s);
        sum += (u_taps[k + u_radius] * u_scales[s]) * imageLoad(u_src, q).rgb;
    }
    vec3 prev = u_accumulate ? imageLoad(u_out, p).rgb : vec3(0.0f);
    imageStore(u_out, p, vec4(prev + u_weight * sum, 0.0f));
}
