// kneiphof2025 GPU prefilter, pass 3: Eq. 19 per texel of the base level.
#include "glintlab/glints/kneiphof2025/kneiphof2025_partition.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_base;
layout(rgba32f, binding = 1) uniform writeonly image2D u_weights_a;
layout(rgba32f, binding = 2) uniform writeonly image2D u_weights_b;
uniform int u_levels;
uniform vec4 u_levels_a;
uniform vec4 u_levels_b;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_base);
    if (p.x >= size.x || p.y >= size.y) return;
    vec4 wa;
    vec4 wb;
    kneiphof2025_partition(imageLoad(u_base, p).a, u_levels, u_levels_a, u_levels_b, wa, wb);
    imageStore(u_weights_a, p, wa);
    imageStore(u_weights_b, p, wb);
}
