// Textured material parameters in the forward pass (docs/MODELS.md,
// "Textured parameters"), the GPU side of glints/glint_textures.cpp and
// render/surface_bsdf.cpp: each texture holds the quantity a footprint
// averages (e^{ln N}, α², linear RGB) with the CPU's mip chain of exact box
// means (core/mip_texture.h), and is read over the pixel footprint by the
// same anisotropic filter as MipTexture::filtered: N = ⌈Pmax/Pmin⌉ ≤ 16
// trilinear probes along the longer derivative at λ = log2(Pmax/N).
// (textureGrad's own anisotropic filter is implementation-defined, and Mesa
// llvmpipe's returns stripes.) Included by forward.frag.glsl after the
// material uniforms when GLINTLAB_MATERIAL_TEXTURES is defined.
#ifndef GLINTLAB_REALTIME_MATERIAL_TEXTURES_GLSL
#define GLINTLAB_REALTIME_MATERIAL_TEXTURES_GLSL

#ifndef GLINTLAB_MATERIAL_TEXTURES
#define GLINTLAB_MATERIAL_TEXTURES 1
#endif
#include "glintlab/core/footprint.glsl"
#include "glintlab/core/texture_filter.glsl"
#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/realtime/shaders/material_uniforms.glsl"

// Slots (gpu_renderer.cpp set_material_textures), texture units 10-15 (forward_shaders.h).
const int MATERIAL_TEXTURE_DENSITY = 0;  // glint: e^{ln N}
const int MATERIAL_TEXTURE_ALPHA_X = 1;  // α² along u (glint or conductor/dielectric/plastic)
const int MATERIAL_TEXTURE_ALPHA_Y = 2;  // α² along v
const int MATERIAL_TEXTURE_COLOR = 3;    // glint colour, or diffuse/plastic albedo
const int MATERIAL_TEXTURE_BASE = 4;     // glint base_albedo
const int MATERIAL_TEXTURE_METALLIC = 5; // metallic-roughness metallic
layout(binding = 10) uniform sampler2D u_material_texture[6];
uniform int u_material_texture_mask;  // bit i: slot i is textured
// Slot 1 holds an isotropic roughness map: α_y is α_x (slot 2 is unset).
uniform int u_material_texture_alpha_isotropic;
// uv' = linear · uv + offset (KHR_texture_transform), level 0's size in texels.
uniform mat2 u_material_texture_linear[6];
uniform vec2 u_material_texture_offset[6];
uniform vec2 u_material_texture_size[6];
// The glint model shears its target by the slopes' correlation
// (GlintModelDescriptor::reads_slope_correlation), which the
// normal map and the curvature add up per fragment.
uniform int u_glint_reads_correlation;

// One-value slots whose maps line up share one texture (the loader's
// pack_scalar_inputs, core/texture_input.h): slot i's value is
// dot(lookup, u_material_texture_channel[i]) (a one-hot selector of its
// channel) of the lookup of slot u_material_texture_source[i], the first
// slot with its texture; only the source slots are looked up. (Selects on
// uniforms, not an array indexed per fragment: llvmpipe spills such arrays.)
uniform int u_material_texture_source[6];
uniform vec4 u_material_texture_channel[6];

// One line: the texture of `slot` over the footprint (a constant slot indexes the sampler array).
#define MATERIAL_TEXTURE(slot, fp) material_texture_filtered4(u_material_texture[slot], u_material_texture_size[slot], u_material_texture_linear[slot], u_material_texture_offset[slot], fp, 0.0f)

vec3 g_albedo;
float g_metallic;
vec2 g_alpha;
vec3 g_glint_color;
vec3 g_glint_base_albedo;

// The per-fragment values every later read of the material's names sees.
void resolve_material_textures(Footprint fp) {
    g_albedo = u_albedo;
    g_metallic = u_metallic;
    g_alpha = u_alpha;
    g_glint_color = u_glint_color;
    g_glint_base_albedo = u_glint_base_albedo;
    g_glint_alpha = glint_alpha_uniform();
    g_glint_log_density = glint_log_density_uniform();
    g_glint_slope_correlation = 0.0f;
    int mask = u_material_texture_mask;
    bool glint = u_material_type == 4;
    // The one-value slots' lookups, each reusing an earlier slot's where they
    // share it (a glint's density and roughness; a metallic-roughness map's
    // roughness and metallic: never density and metallic).
    vec4 l0 = vec4(0.0f), l1 = vec4(0.0f), l2 = vec4(0.0f), l5 = vec4(0.0f);
    if ((mask & (1 << MATERIAL_TEXTURE_DENSITY)) != 0)
        l0 = MATERIAL_TEXTURE(MATERIAL_TEXTURE_DENSITY, fp);
    if ((mask & (1 << MATERIAL_TEXTURE_ALPHA_X)) != 0) {
        if (u_material_texture_source[MATERIAL_TEXTURE_ALPHA_X] == 0)
            l1 = l0;
        else
            l1 = MATERIAL_TEXTURE(MATERIAL_TEXTURE_ALPHA_X, fp);
    }
    if ((mask & (1 << MATERIAL_TEXTURE_ALPHA_Y)) != 0) {
        int source = u_material_texture_source[MATERIAL_TEXTURE_ALPHA_Y];
        if (source == 0)
            l2 = l0;
        else if (source == 1)
            l2 = l1;
        else
            l2 = MATERIAL_TEXTURE(MATERIAL_TEXTURE_ALPHA_Y, fp);
    }
    if ((mask & (1 << MATERIAL_TEXTURE_METALLIC)) != 0) {
        int source = u_material_texture_source[MATERIAL_TEXTURE_METALLIC];
        if (source == 1)
            l5 = l1;
        else if (source == 2)
            l5 = l2;
        else
            l5 = MATERIAL_TEXTURE(MATERIAL_TEXTURE_METALLIC, fp);
    }
    if ((mask & (1 << MATERIAL_TEXTURE_DENSITY)) != 0)
        g_glint_log_density = log(max(dot(l0, u_material_texture_channel[0]), 1e-30f));
    if ((mask & (1 << MATERIAL_TEXTURE_ALPHA_X)) != 0) {
        float a2 = max(dot(l1, u_material_texture_channel[1]), 0.0f);
        if (glint)
            g_glint_alpha.x = clamp(sqrt(a2), 1e-3f, 1.0f);  // glint_textures.cpp alpha_from_squared
        else
            g_alpha.x = sqrt(a2);
        if (u_material_texture_alpha_isotropic != 0) {
            if (glint)
                g_glint_alpha.y = g_glint_alpha.x;
            else
                g_alpha.y = g_alpha.x;
        }
    }
    if ((mask & (1 << MATERIAL_TEXTURE_ALPHA_Y)) != 0) {
        float a2 = max(dot(l2, u_material_texture_channel[2]), 0.0f);
        if (glint)
            g_glint_alpha.y = clamp(sqrt(a2), 1e-3f, 1.0f);
        else
            g_alpha.y = sqrt(a2);
    }
    if ((mask & (1 << MATERIAL_TEXTURE_COLOR)) != 0) {
        vec3 c = MATERIAL_TEXTURE(MATERIAL_TEXTURE_COLOR, fp).rgb;
        if (glint)
            g_glint_color = c;
        else
            g_albedo = c;
    }
    if ((mask & (1 << MATERIAL_TEXTURE_BASE)) != 0)
        g_glint_base_albedo = MATERIAL_TEXTURE(MATERIAL_TEXTURE_BASE, fp).rgb;
    if ((mask & (1 << MATERIAL_TEXTURE_METALLIC)) != 0)
        g_metallic = clamp(dot(l5, u_material_texture_channel[5]), 0.0f, 1.0f);
}

#define u_albedo g_albedo
#define u_metallic g_metallic
#define u_alpha g_alpha
#define u_glint_color g_glint_color
#define u_glint_base_albedo g_glint_base_albedo

#endif
