// The footprint filter of every textured input on the GPU, the GLSL twin
// of MipTexture::filtered (core/mip_texture.h): N = ceil(Pmax / Pmin) <= 16
// trilinear probes along the longer derivative at lambda = log2(Pmax / N) +
// bias. (textureGrad's own anisotropic filter is implementation-defined, and
// Mesa llvmpipe's returns stripes.) Used by the forward pass's material
// textures and normal maps and by the exported shader's input textures.
#ifndef GLINTLAB_CORE_TEXTURE_FILTER_GLSL
#define GLINTLAB_CORE_TEXTURE_FILTER_GLSL

#include "glintlab/core/footprint.glsl"

const int kMaterialTextureMaxAnisotropy = 16;

// `bias`: OpenGL's TEXTURE_LOD_BIAS (MipTexture::filtered's lod_bias).
vec4 material_texture_filtered4(sampler2D tex, vec2 size, mat2 linear, vec2 offset, Footprint fp,
                                float bias) {
    vec2 st = linear * fp.uv + offset;
    vec2 dx = linear * fp.duvdx, dy = linear * fp.duvdy;
    float px = length(dx * size), py = length(dy * size);
    float pmax = max(px, py), pmin = min(px, py);
    if (!(pmax > 0.0f) || isinf(pmax)) return textureLod(tex, st, 0.0f);
    int n = int(min(float(kMaterialTextureMaxAnisotropy), ceil(pmax / max(pmin, pmax * 1e-6f))));
    float lod = log2(pmax / float(n)) + bias;
    vec2 major = px >= py ? dx : dy;
    vec4 sum = vec4(0.0f);
    for (int i = 0; i < n; ++i)
        sum += textureLod(tex, st + major * ((float(i) + 0.5f) / float(n) - 0.5f), lod);
    return sum / float(n);
}

#endif
