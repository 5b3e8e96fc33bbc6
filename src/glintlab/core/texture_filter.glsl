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

// LEAN's footprint statistics of a normal map (core/normal_map.cpp
// NormalMap::lookup): the mean slope and Σ = (xx, yy, xy), the chain's
// where the footprint spans a texel or more, the finest level's own surface
// below half a texel (slope_frame.glsl lean_blend_surface), blended
// between. `slopes` holds (s_x, s_y, s_x², s_y²), `cross` s_x s_y (read only
// where `correlated`; any sampler otherwise). The chain's lookups are
// skipped where its weight is 0, the five level-0 fetches where it is 1.
void lean_statistics(sampler2D slopes, sampler2D cross, vec2 size, mat2 linear, vec2 offset,
                     Footprint fp, bool correlated, out vec2 mean, out vec3 cov) {
    mean = vec2(0.0f);
    cov = vec3(0.0f);
    float t = lean_chain_weight(material_texture_lod(size, linear, fp, kSlopeMomentLodBias));
    if (t > 0.0f) {
        vec4 first =
            material_texture_filtered4(slopes, size, linear, offset, fp, kSlopeMomentLodBias);
        float second_xy = correlated ? material_texture_filtered4(cross, size, linear, offset, fp,
                                                                  kSlopeMomentLodBias)
                                           .x
                                     : 0.0f;
        mean = first.xy;
        cov = slope_covariance(mean, first.zw, second_xy, correlated);
    }
    if (t < 1.0f) {
        vec2 st = linear * fp.uv + offset;
        vec2 hx = 0.5f * (linear * fp.duvdx), hy = 0.5f * (linear * fp.duvdy);
        lean_blend_surface(
            t, textureLod(slopes, st, 0.0f).xy, textureLod(slopes, st + hx, 0.0f).xy,
            textureLod(slopes, st - hx, 0.0f).xy, textureLod(slopes, st + hy, 0.0f).xy,
            textureLod(slopes, st - hy, 0.0f).xy, correlated, mean, cov);
    }
}

#endif
