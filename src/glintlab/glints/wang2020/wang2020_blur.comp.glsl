// wang2020 (Wang et al. 2020, 001) §4.4 screen-space post-process, on the GPU
// (glints/wang2020/wang2020_gpu_blur.h): one axis of a clamped separable Gaussian.
// u_mode selects what is blurred: 0: the source's visibility (a) -> r;
// 1: the source as is; 2: rgb of the source times δ (r of u_aux).
// u_store_aux: a of the output = r of u_aux (δ).
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_src;
layout(rgba32f, binding = 1) uniform readonly image2D u_aux;
layout(rgba32f, binding = 2) uniform writeonly image2D u_out;
uniform float u_taps[31];
uniform int u_radius;
uniform int u_axis;  // 0: x, 1: y
uniform int u_mode;
uniform bool u_store_aux;
vec4 fetch(ivec2 q) {
    vec4 s = imageLoad(u_src, q);
    if (u_mode == 0) return vec4(s.a, 0.0f, 0.0f, 0.0f);
    if (u_mode == 2) return vec4(s.rgb * imageLoad(u_aux, q).r, 0.0f);
    return s;
}
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_src);
    if (any(greaterThanEqual(p, size))) return;
    vec4 sum = vec4(0.0f);
    for (int k = -u_radius; k <= u_radius; ++k) {
        ivec2 q = p;
        if (u_axis == 0) q.x = clamp(p.x + k, 0, size.x - 1);
        else q.y = clamp(p.y + k, 0, size.y - 1);
        sum += u_taps[k + u_radius] * fetch(q);
    }
    if (u_store_aux) sum.a = imageLoad(u_aux, p).r;
    imageStore(u_out, p, sum);
}
