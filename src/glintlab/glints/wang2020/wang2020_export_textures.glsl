// wang2020's glue with its tables in textures instead of SSBOs, for
// `glintlab export` (export/shader_export.h): GLSL ES 3.00 (WebGL2) has no
// storage buffers. Each table is the renderer's array unchanged, laid out
// row-major in a texture WANG2020_TABLE_WIDTH (4096) texels wide (element i at
// texel (i % width, i / width)): DPF R32F, prefiltered environment RGBA32F,
// quadtree nodes RG32UI, the environment the particles reflect RGBA32F, all read with
// texelFetch (no filtering).
#ifndef GLINTLAB_GLINTS_WANG2020_EXPORT_TEXTURES_GLSL
#define GLINTLAB_GLINTS_WANG2020_EXPORT_TEXTURES_GLSL

#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/glints/wang2020/wang2020_tables.glsl"
const int WANG2020_TABLE_WIDTH = 4096;
uniform sampler2D u_wang2020_dpf_texture;
uniform sampler2D u_wang2020_prefilter_texture;
uniform highp usampler2D u_wang2020_nodes_texture;
uniform sampler2D u_wang2020_cone_texture;
ivec2 wang2020_texel(int index) {
    return ivec2(index % WANG2020_TABLE_WIDTH, index / WANG2020_TABLE_WIDTH);
}
float wang2020_dpf_value(int index) {
    return texelFetch(u_wang2020_dpf_texture, wang2020_texel(index), 0).x;
}
vec4 wang2020_prefilter_value(int index) {
    return texelFetch(u_wang2020_prefilter_texture, wang2020_texel(index), 0);
}
uvec2 wang2020_node(int index) {
    uvec4 v = texelFetch(u_wang2020_nodes_texture, wang2020_texel(index), 0);
    return uvec2(v.x, v.y);
}
vec4 wang2020_cone_value(int index) {
    return texelFetch(u_wang2020_cone_texture, wang2020_texel(index), 0);
}
#include "glintlab/glints/wang2020/wang2020_glue_common.glsl"

#endif
