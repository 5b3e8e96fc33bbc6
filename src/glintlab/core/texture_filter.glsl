// The footprint filter of every textured input on the GPU, the GLSL twin
// of MipTexture::filtered (core/mip_texture.h): N = ceil(Pmax / Pmin) <= 16
// trilinear probes along the longer derivative at lambda = log2(Pmax / N) +
// bias. (textureGrad's own anisotropic filter is implementation-defined, and
// Mesa llvmpipe's returns stripes.) Used by the forward pass's material
// textures and normal maps and by the exported shader's input textures.
#ifndef GLINTLAB_CORE_TEXTURE_FILTER_GLSL
#define GLINTLAB_CORE_TEXTURE_FILTER_GLSL

#include "glintlab/core/footprint.glsl"
#include "glintlab/core/slope_frame.glsl"

const int kMaterialTextureMaxAnisotropy = 16;

// The probes' count N and λ (MipTexture::filter_lod) for texel extents px, py.
int material_texture_probes(float px, float py) {
    float pmax = max(px, py), pmin = min(px, py);
    return int(min(float(kMaterialTextureMaxAnisotropy), ceil(pmax / max(pmin, pmax * 1e-6f))));
}
float material_texture_probe_lod(float px, float py, int n, float bias) {
    return log2(max(px, py) / float(n)) + bias;
}
// λ of a footprint's probes, bias included; +∞ where the footprint is not
// finite (the coarsest level), −∞ where it is empty (level 0).
float material_texture_lod(vec2 size, mat2 linear, Footprint fp, float bias) {
    vec2 dx = linear * fp.duvdx, dy = linear * fp.duvdy;
    float px = length(dx * size), py = length(dy * size);
    if (isinf(px) || isinf(py) || isnan(px) || isnan(py)) return 1e30f;
    if (!(max(px, py) > 0.0f)) return -1e30f;
    return material_texture_probe_lod(px, py, material_texture_probes(px, py), bias);
}

// `bias`: OpenGL's TEXTURE_LOD_BIAS (MipTexture::filtered's lod_bias).
vec4 material_texture_filtered4(sampler2D tex, vec2 size, mat2 linear, vec2 offset, Footprint fp,
                                float bias) {
    vec2 st = linear * fp.uv + offset;
    vec2 dx = linear * fp.duvdx, dy = linear * fp.duvdy;
    float px = length(dx * size), py = length(dy * size);
    float pmax = max(px, py);
    if (!(pmax > 0.0f) || isinf(pmax)) return textureLod(tex, st, 0.0f);
    int n = material_texture_probes(px, py);
    float lod = material_texture_probe_lod(px, py, n, bias);
    vec2 major = px >= py ? dx : dy;
    vec4 sum = vec4(0.0f);
    for (int i = 0; i < n; ++i)
        sum += textureLod(tex, st + major * ((float(i) + 0.5f) / float(n) - 0.5f), lod);
    return sum / float(n);
}

// The weight of a normal map's chain at the footprint (slope_frame.glsl
// lean_chain_weight): 0 needs no chain lookup, 1 no surface fetches.
float lean_footprint_chain_weight(vec2 size, mat2 linear, Footprint fp) {
    return lean_chain_weight(material_texture_lod(size, linear, fp, kSlopeMomentLodBias));
}

// LEAN's footprint statistics (mean, cov) with the finest level's own
// surface blended in under footprints below a texel (core/normal_map.cpp):
// `slopes` holds (s_x, s_y, s_x², s_y²), (mean, cov) are the chain's (any
// value where t = 0), t = lean_footprint_chain_weight < 1.
void lean_magnified(sampler2D slopes, mat2 linear, vec2 offset, Footprint fp, float t,
                    bool correlated, inout vec2 mean, inout vec3 cov) {
    vec2 st = linear * fp.uv + offset;
    vec2 hx = 0.5f * (linear * fp.duvdx), hy = 0.5f * (linear * fp.duvdy);
    lean_blend_surface(t, textureLod(slopes, st, 0.0f).xy, textureLod(slopes, st + hx, 0.0f).xy,
                       textureLod(slopes, st - hx, 0.0f).xy, textureLod(slopes, st + hy, 0.0f).xy,
                       textureLod(slopes, st - hy, 0.0f).xy, correlated, mean, cov);
}

#endif
