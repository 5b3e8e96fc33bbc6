// kneiphof2025 GPU prefilter, pass 6 (Resolution::Reduced,
// kneiphof2025_prefilter_gpu.h): one layer filtered on a coarser grid (mip
// level u_lod of the coarse arrays) upsampled to W x H by bilinear
// interpolation at the texel centres (u wraps, v clamps at the coarse texel
// centres, as the forward shader's own bilinear lookups within a layer).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2DArray u_coarse0;
layout(binding = 1) uniform sampler2DArray u_coarse1;
layout(binding = 2) uniform sampler2DArray u_coarse2;
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_out0;
layout(rgba32f, binding = 1) uniform writeonly image2DArray u_out1;
layout(rgba32f, binding = 2) uniform writeonly image2DArray u_out2;
uniform int u_layer;
uniform float u_lod;       // s_m: an integer level (GL_LINEAR_MIPMAP_NEAREST)
uniform bool u_weights_b;  // K = 8 (weights 5-8 are zero for K = 4)
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec3 size = imageSize(u_out0);
    if (p.x >= size.x || p.y >= size.y) return;
    vec3 uvw = vec3((vec2(p) + 0.5f) / vec2(size.xy), float(u_layer));
    imageStore(u_out0, ivec3(p, u_layer), vec4(textureLod(u_coarse0, uvw, u_lod).rgb, 0.0f));
    imageStore(u_out1, ivec3(p, u_layer), textureLod(u_coarse1, uvw, u_lod));
    imageStore(u_out2, ivec3(p, u_layer),
               u_weights_b ? textureLod(u_coarse2, uvw, u_lod) : vec4(0.0f));
}
