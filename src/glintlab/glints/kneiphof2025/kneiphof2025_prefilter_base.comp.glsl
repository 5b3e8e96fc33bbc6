// kneiphof2025 (Kneiphof & Klein 2025, 003) GPU prefilter
// (glints/kneiphof2025/kneiphof2025_prefilter_gpu.h),
// pass 1: base level (Kneiphof2025Environment's level 0: ss x ss bilinear
// source samples per texel, the CPU's source_sample), its luminance in
// alpha, and the luminance range by atomics on the float bits (luminance
// >= 0, so the unsigned order is the float order).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_source;
layout(rgba32f, binding = 0) uniform writeonly image2D u_base;
layout(std430, binding = 0) buffer Range { uint u_min_bits; uint u_max_bits; };
uniform int u_ss;
uniform float u_scale;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_base);
    if (p.x >= size.x || p.y >= size.y) return;
    vec3 c = vec3(0.0f);
    for (int j = 0; j < u_ss; ++j)
        for (int i = 0; i < u_ss; ++i) {
            vec2 uv = vec2((float(p.x) + (float(i) + 0.5f) / float(u_ss)) / float(size.x),
                           (float(p.y) + (float(j) + 0.5f) / float(u_ss)) / float(size.y));
            c += textureLod(u_source, uv, 0.0f).rgb * u_scale;
        }
    c /= float(u_ss * u_ss);
    float lum = max(0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b, 0.0f);  // core/image luminance
    imageStore(u_base, p, vec4(c, lum));
    atomicMin(u_min_bits, floatBitsToUint(lum));
    atomicMax(u_max_bits, floatBitsToUint(lum));
}
