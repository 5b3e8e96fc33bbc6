// kneiphof2025 GPU prefilter, pass 4: one 2 x 2 box reduction of the three
// pyramids (the CPU's order of summation: row by row, then / 4).
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_src0;
layout(rgba32f, binding = 1) uniform readonly image2D u_src1;
layout(rgba32f, binding = 2) uniform readonly image2D u_src2;
layout(rgba32f, binding = 3) uniform writeonly image2D u_dst0;
layout(rgba32f, binding = 4) uniform writeonly image2D u_dst1;
layout(rgba32f, binding = 5) uniform writeonly image2D u_dst2;
vec4 reduce(ivec2 q, int which) {
    vec4 s = vec4(0.0f);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            ivec2 t = 2 * q + ivec2(i, j);
            s += which == 0 ? imageLoad(u_src0, t) : which == 1 ? imageLoad(u_src1, t) : imageLoad(u_src2, t);
        }
    return s / 4.0f;
}
void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_dst0);
    if (q.x >= size.x || q.y >= size.y) return;
    imageStore(u_dst0, q, reduce(q, 0));
    imageStore(u_dst1, q, reduce(q, 1));
    imageStore(u_dst2, q, reduce(q, 2));
}
