// kneiphof2025 GPU prefilter, pass 5: the split-sum prefilter of one layer
// (Eq. 11, 21): every channel filtered by the same kernel around n = map
// direction of the texel (Kneiphof2025Environment's loop: Duff et al. basis,
// map_uv without rotation, trilinear pyramid lookups, weighted mean).
// Layer 0 (u_count = 0) copies the base level. The output images are the
// layer's grid: W x H, or a coarser mip level in Resolution::Reduced (the
// texel centres of that grid; kneiphof2025_prefilter_gpu.h).
#include "glintlab/core/constants.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_pyramid0;
layout(binding = 1) uniform sampler2D u_pyramid1;
layout(binding = 2) uniform sampler2D u_pyramid2;
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_out0;
layout(rgba32f, binding = 1) uniform writeonly image2DArray u_out1;
layout(rgba32f, binding = 2) uniform writeonly image2DArray u_out2;
// The kernels of every layer: per sample (l.xyz, weight), (lod, 0, 0, 0).
layout(std430, binding = 0) readonly buffer Kernels { vec4 u_kernels[]; };
uniform int u_layer;
uniform int u_first;  // first sample of this layer's kernel
uniform int u_count;       // kernel samples (0: copy level 0)
uniform bool u_weights_b;  // K = 8: weights 5-8 are read (all zero for K = 4)
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec3 size = imageSize(u_out0);
    if (p.x >= size.x || p.y >= size.y) return;
    vec4 a0 = vec4(0.0f);
    vec4 a1 = vec4(0.0f);
    vec4 a2 = vec4(0.0f);
    if (u_count == 0) {
        a0 = texelFetch(u_pyramid0, p, 0);
        a1 = texelFetch(u_pyramid1, p, 0);
        a2 = texelFetch(u_pyramid2, p, 0);
    } else {
        // kneiphof2025_prefilter.cpp map_direction at the texel centre.
        float theta = (float(p.y) + 0.5f) / float(size.y) * PI;
        float phi = ((float(p.x) + 0.5f) / float(size.x) - 0.5f) * 2.0f * PI;
        float st = sin(theta);
        vec3 n = vec3(st * sin(phi), cos(theta), -st * cos(phi));
        float sgn = n.z >= 0.0f ? 1.0f : -1.0f;
        float a = -1.0f / (sgn + n.z);
        float b = n.x * n.y * a;
        vec3 t = vec3(1.0f + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
        vec3 bt = vec3(b, sgn + n.y * n.y * a, -n.y);
        float wsum = 0.0f;
        for (int k = 0; k < u_count; ++k) {
            vec4 s = u_kernels[2 * (u_first + k)];
            vec3 d = s.x * t + s.y * bt + s.z * n;
            float u = 0.5f + atan(d.x, -d.z) / (2.0f * PI);
            u -= floor(u);
            vec2 uv = vec2(u, acos(clamp(d.y, -1.0f, 1.0f)) / PI);
            float lod = u_kernels[2 * (u_first + k) + 1].x;
            a0 += s.w * textureLod(u_pyramid0, uv, lod);
            a1 += s.w * textureLod(u_pyramid1, uv, lod);
            if (u_weights_b) a2 += s.w * textureLod(u_pyramid2, uv, lod);
            wsum += s.w;
        }
        if (wsum > 0.0f) {
            a0 /= wsum;
            a1 /= wsum;
            a2 /= wsum;
        }
    }
    imageStore(u_out0, ivec3(p, u_layer), vec4(a0.rgb, 0.0f));
    imageStore(u_out1, ivec3(p, u_layer), a1);
    imageStore(u_out2, ivec3(p, u_layer), a2);
}
