// Normal maps in the forward pass (docs/MODELS.md, "Normal maps"): the GPU
// side of core/normal_map.cpp (LEAN lookup of the slopes' first and second
// moments over the footprint, the moments at kMomentLodBias) and of
// render/surface_bsdf.cpp (local_bump's axes, the frame tilted to the mean
// normal, α² + 2Σ). Included by forward.frag.glsl after
// material_textures.glsl when GLINTLAB_NORMAL_MAP is defined; the program
// is then also the textured-material variant, whose per-fragment α this
// file widens.
#ifndef GLINTLAB_REALTIME_NORMAL_MAP_GLSL
#define GLINTLAB_REALTIME_NORMAL_MAP_GLSL

// material_textures.glsl first: it turns on the per-fragment α the
// uniforms' includes then declare.
#include "glintlab/realtime/shaders/material_textures.glsl"
#include "glintlab/core/footprint.glsl"
#include "glintlab/core/footprint_cell.glsl"
#include "glintlab/core/slope_frame.glsl"
#include "glintlab/glints/material.glsl"

// Units 16 and 17 (forward_shaders.h kNormalMapUnit): the map's mip chains
// of (s_x, s_y, s_x², s_y²) and s_x s_y (NormalMap's slopes and
// cross_moment), one uv transform for both. A glint lobe and an
// anisotropic one take Σ's diagonal only: one lookup.
layout(binding = 16) uniform sampler2D u_normal_slopes;
layout(binding = 17) uniform sampler2D u_normal_moments;
uniform mat2 u_normal_map_linear;
uniform vec2 u_normal_map_offset;
uniform vec2 u_normal_map_size;
uniform int u_normal_map_filtering;     // 0: lean, 1: none (the finest level's normal)
uniform int u_normal_map_widens_glint;  // the glint model reads a per-pixel α

// Tilts (t, b, n) to the footprint's mean normal, kept facing wo_world
// (visible_slope), and widens the material's α by the slope covariance, as
// make_surface_bsdf does. `back`: the frame was flipped to the side of wo;
// `bitangent_sign`: the tangent's w.
// `glint_cov_xy` gains the map's Σ_xy in the shading frame where the glint
// model reads the slopes' correlation (u_glint_reads_correlation).
void normal_map_shade(Footprint fp, bool back, float bitangent_sign, vec3 wo_world,
                      inout vec3 t, inout vec3 b, inout vec3 n, inout SurfaceMaterial mat,
                      inout float glint_cov_xy) {
    bool lean = u_normal_map_filtering == 0;
    vec2 mean = vec2(0.0f);
    vec3 cov = vec3(0.0f);
    if (!lean) {
        mean = textureLod(u_normal_slopes, u_normal_map_linear * fp.uv + u_normal_map_offset, 0.0f)
                   .xy;
    } else {
        // Σ's correlation turns every lobe but a diffuse one and the glint
        // lobes of models that drop it.
        bool correlated = mat.type == MATERIAL_GLINT
                              ? u_normal_map_widens_glint != 0 && u_glint_reads_correlation != 0
                              : mat.type != MATERIAL_DIFFUSE;
        lean_statistics(u_normal_slopes, u_normal_moments, u_normal_map_size, u_normal_map_linear,
                        u_normal_map_offset, fp, correlated, mean, cov);
    }
    slopes_in_shading_frame(back, bitangent_sign, mean, cov);
    mean = visible_slope(mean, vec3(dot(wo_world, t), dot(wo_world, b), dot(wo_world, n)));
    tilt_frame_to_slope(mean, t, b, n);
    if (mat.type == MATERIAL_DIFFUSE) return;
    if (mat.type == MATERIAL_GLINT) {
        // Glint NDF axes stay on the uv axes: Σ_xy shears the target of the
        // models that read it (forward.frag.glsl), the others drop it.
        if (u_normal_map_widens_glint != 0) {
            mat.glint.alpha_x = slope_widened_alpha(mat.glint.alpha_x, cov.x, 1.0f);
            mat.glint.alpha_y = slope_widened_alpha(mat.glint.alpha_y, cov.y, 1.0f);
            g_glint_alpha = vec2(mat.glint.alpha_x, mat.glint.alpha_y);
            glint_cov_xy += cov.z;
        }
        return;
    }
    // The widened lobe along its principal axes (render/surface_bsdf.cpp).
    vec3 lobe = principal_slope_lobe(slope_widened_alpha(mat.alpha_x, cov.x, 4.0f),
                                     slope_widened_alpha(mat.alpha_y, cov.y, 4.0f), cov.z, 4.0f);
    mat.alpha_x = lobe.x;
    mat.alpha_y = lobe.y;
    if (lobe.z != 0.0f) {
        vec3 tr = cos(lobe.z) * t + sin(lobe.z) * b;
        t = tr;
        b = cross(n, tr);
    }
    g_alpha = vec2(mat.alpha_x, mat.alpha_y);
}

#endif
