// The fragment stage of `glintlab export` (export/shader_export.h,
// docs/INTEGRATION.md): the glint material of one model under up to
// GLINT_MAX_LIGHTS directional and point lights (and, for models that shade
// it themselves, the environment), as the forward pass
// (realtime/shaders/forward.frag.glsl) shades a glint material without
// shadows. The exporter puts the model's glue (glints/**/*_gpu.glsl or its
// export variant) ahead of this file and flattens the includes.
//
// Entry points for a host that keeps its own fragment stage:
//     Footprint glint_footprint(vec2 uv);  // call in uniform control flow
//     void glint_set_inputs(GlintInputs inputs);  // per-pixel material inputs
//     vec3 glint_shade(vec3 p, vec3 n_geo, vec3 dpdu, Footprint fp);
//     vec3 glint_eval(vec3 wo, vec3 wi, Footprint fp);  // f(wo, wi) cos(wi)
// and, where the model reads the pixel's view differentials
// (GLINTLAB_GLINT_VIEW_DIFFERENTIALS: chermain2020's geometric glint
// anti-aliasing),
//     void glint_view_derivatives(vec3 p, vec3 n);  // call in uniform control flow
//     void glint_set_view_derivatives(vec3 dwo_dx, vec3 dwo_dy, vec3 dn_dx, vec3 dn_dy);
// The exporter defines GLINTLAB_MATERIAL_TEXTURES ahead of the glue: the
// names u_glint_alpha and u_glint_log_density the glue reads are then
// per-fragment values (glint_uniforms.glsl), set by glint_set_inputs.
#include "glintlab/core/constants.glsl"
#include "glintlab/core/footprint.glsl"
#include "glintlab/core/slope_frame.glsl"
#include "glintlab/core/texture_filter.glsl"
#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/glints/material.glsl"

const int GLINT_MAX_LIGHTS = 4;

in vec3 v_position;   // world position
in vec3 v_normal;     // world shading normal (normalized here)
in vec2 v_uv;         // the glint pattern's coordinates (its density is per unit uv area)
in vec3 v_dpdu;       // world dp/du: the tangent of the shading frame
out vec4 o_radiance;  // linear radiance, alpha 1

uniform vec3 u_eye;  // world camera position
// The glint material (GlintDesc, scene.h): colour, optional diffuse base
// under a dielectric coat, masking (GLINT_G2_*); its Fresnel u_fresnel_*
// (GLINT_FRESNEL_*) is declared in glint_uniforms.glsl.
uniform vec3 u_glint_color;
// 1: the material's "curvature" is "footprint" (main() adds the surface's
// curvature to the slope variance); 0: "none", the default.
uniform int u_glint_curvature;
uniform vec3 u_glint_base_albedo;
uniform int u_glint_g2;
// Lights: directional (world direction towards the light, irradiance) and
// point (world position, intensity W/sr per channel), first `count` used.
uniform int u_directional_count;
uniform vec3 u_directional_direction[GLINT_MAX_LIGHTS];
uniform vec3 u_directional_irradiance[GLINT_MAX_LIGHTS];
uniform int u_point_count;
uniform vec3 u_point_position[GLINT_MAX_LIGHTS];
uniform vec3 u_point_intensity[GLINT_MAX_LIGHTS];
// The model's own image-based lighting (kneiphof2025, wang2020).
uniform bool u_environment_on;

// Per-pixel material inputs (docs/INTEGRATION.md, "Per-pixel material
// inputs"): what a host may read from its own textures. Each is the value
// at the pixel after filtering over its footprint in the quantity stated:
struct GlintInputs {
    float log_density;  // ln N; filter N = exp(ln N) (the footprint's expected count), then log
    vec2 alpha;         // (alpha_x, alpha_y); filter alpha² (the slope variance), then sqrt
    vec3 color;         // linear RGB tint; filter linearly
    vec3 base_albedo;   // linear RGB diffuse base (0: none); filter linearly
    // A normal map over the footprint (LEAN mapping): its mean slope
    // (s_x, s_y) = (−x/z, −y/z) of the tangent-space normal, in the frame
    // (t, n × t, n) of glint_shade's v_dpdu and v_normal, and its slope
    // variances (Σ_xx, Σ_yy); filter s and (s_x², s_y²), then
    // Σ_ii = E[s_i²] − s̄_i². Zero: no normal map.
    vec2 mean_slope;
    vec2 slope_variance;
    // Σ_xy = E[s_x s_y] − s̄_x s̄_y in the same frame: read by the models
    // that shear their NDF by the slopes' correlation (chermain2020,
    // GLINTLAB_GLINT_SLOPE_CORRELATION); the others keep uv-aligned axes.
    float slope_covariance_xy;
};
vec3 g_glint_color_input;
vec3 g_glint_base_albedo_input;
vec2 g_glint_mean_slope;
float g_glint_front_correlation;  // the slopes' correlation seen from the front

// The material uniforms as inputs (a material without textures).
GlintInputs glint_inputs_from_uniforms() {
    GlintInputs inputs;
    inputs.log_density = glint_log_density_uniform();
    inputs.alpha = glint_alpha_uniform();
    inputs.color = u_glint_color;
    inputs.base_albedo = u_glint_base_albedo;
    inputs.mean_slope = vec2(0.0f);
    inputs.slope_variance = vec2(0.0f);
    inputs.slope_covariance_xy = 0.0f;
    return inputs;
}

// Sets the inputs every later glint_shade / glint_eval reads. A normal
// map's slope variances widen the glint lobe (α² + 2Σ_ii per axis) for the
// models that read a per-pixel α; glint_shade tilts its frame to the mean
// slope.
void glint_set_inputs(GlintInputs inputs) {
    g_glint_log_density = inputs.log_density;
    vec2 alpha = clamp(inputs.alpha, vec2(1e-3f), vec2(1.0f));
#ifdef GLINTLAB_GLINT_PER_PIXEL_ALPHA
    alpha = vec2(slope_widened_alpha(alpha.x, max(inputs.slope_variance.x, 0.0f), 1.0f),
                 slope_widened_alpha(alpha.y, max(inputs.slope_variance.y, 0.0f), 1.0f));
#endif
    g_glint_alpha = alpha;
    g_glint_front_correlation = 0.0f;
#ifdef GLINTLAB_GLINT_SLOPE_CORRELATION
    g_glint_front_correlation = slope_correlation(inputs.slope_covariance_xy, alpha.x, alpha.y);
#endif
    g_glint_slope_correlation = g_glint_front_correlation;
    g_glint_color_input = inputs.color;
    g_glint_base_albedo_input = inputs.base_albedo;
    g_glint_mean_slope = inputs.mean_slope;
}

// Optional input textures the exported main() reads (bit i of
// u_input_texture_mask: input i is textured; 0: every input from the
// uniforms). Each holds the filtered quantity of GlintInputs (N, alpha²,
// linear RGB, slope moments) with a mip chain of box means, read with the
// renderer's own footprint filter (N = ceil(Pmax / Pmin) <= 16 trilinear
// probes along the major axis, core/texture_filter.glsl), at uv' =
// u_input_texture_linear[i] uv + u_input_texture_offset[i].
const int GLINT_INPUT_DENSITY = 0;  // N = exp(ln N), one channel
const int GLINT_INPUT_ALPHA = 1;    // alpha² (isotropic), one channel
const int GLINT_INPUT_COLOR = 2;    // linear RGB
const int GLINT_INPUT_BASE = 3;     // linear RGB
const int GLINT_INPUT_NORMAL = 4;   // the normal map's (s_x, s_y, s_x², s_y²), RGBA
// The normal map's s_x s_y, one channel, with GLINT_INPUT_NORMAL's uv
// transform; read only where the model takes the slopes' correlation.
const int GLINT_INPUT_NORMAL_CROSS = 5;
uniform sampler2D u_input_density;
uniform sampler2D u_input_alpha;
uniform sampler2D u_input_color;
uniform sampler2D u_input_base_albedo;
uniform sampler2D u_input_normal_slopes;
uniform sampler2D u_input_normal_cross;
uniform int u_input_texture_mask;
uniform mat2 u_input_texture_linear[5];
uniform vec2 u_input_texture_offset[5];
// The mesh's uvs are mirrored (glTF tangent w = −1): the normal map's y
// runs along −(n × t).
uniform bool u_input_uv_mirrored;

vec3 glint_input_filtered(sampler2D tex, int slot, Footprint fp, float lod_bias) {
    return material_texture_filtered4(tex, vec2(textureSize(tex, 0)), u_input_texture_linear[slot],
                                      u_input_texture_offset[slot], fp, lod_bias)
        .rgb;
}

// The uniforms' inputs with the textured ones replaced by their filtered values.
GlintInputs glint_inputs_from_textures(Footprint fp) {
    GlintInputs inputs = glint_inputs_from_uniforms();
    int mask = u_input_texture_mask;
    if ((mask & (1 << GLINT_INPUT_DENSITY)) != 0)
        inputs.log_density = log(
            max(glint_input_filtered(u_input_density, GLINT_INPUT_DENSITY, fp, 0.0f).x, 1e-30f));
    if ((mask & (1 << GLINT_INPUT_ALPHA)) != 0)
        inputs.alpha = vec2(
            sqrt(max(glint_input_filtered(u_input_alpha, GLINT_INPUT_ALPHA, fp, 0.0f).x, 0.0f)));
    if ((mask & (1 << GLINT_INPUT_COLOR)) != 0)
        inputs.color = glint_input_filtered(u_input_color, GLINT_INPUT_COLOR, fp, 0.0f);
    if ((mask & (1 << GLINT_INPUT_BASE)) != 0)
        inputs.base_albedo = glint_input_filtered(u_input_base_albedo, GLINT_INPUT_BASE, fp, 0.0f);
    if ((mask & (1 << GLINT_INPUT_NORMAL)) != 0) {
        // LEAN mapping, read as the renderer reads its normal maps. The
        // cross moments' sampler exists only where the model reads them.
        vec2 mean;
        vec3 cov;
        vec2 size = vec2(textureSize(u_input_normal_slopes, 0));
        mat2 linear = u_input_texture_linear[GLINT_INPUT_NORMAL];
        vec2 offset = u_input_texture_offset[GLINT_INPUT_NORMAL];
#ifdef GLINTLAB_GLINT_SLOPE_CORRELATION
        lean_statistics(u_input_normal_slopes, u_input_normal_cross, size, linear, offset, fp,
                        (mask & (1 << GLINT_INPUT_NORMAL_CROSS)) != 0, mean, cov);
#else
        lean_statistics(u_input_normal_slopes, u_input_normal_slopes, size, linear, offset, fp,
                        false, mean, cov);
#endif
        slopes_in_shading_frame(false, u_input_uv_mirrored ? -1.0f : 1.0f, mean, cov);
        inputs.mean_slope = mean;
        inputs.slope_variance = cov.xy;
        inputs.slope_covariance_xy = cov.z;
    }
    return inputs;
}

GlintMaterial glint_material() {
    GlintMaterial m;
    m.color = g_glint_color_input;
    m.base_albedo = g_glint_base_albedo_input;
    m.fresnel_mode = u_fresnel_mode;
    m.fresnel_f0 = u_fresnel_f0;
    m.fresnel_eta = u_fresnel_eta;
    m.fresnel_k = u_fresnel_k;
    m.ndf = u_glint_ndf;
    m.alpha_x = u_glint_alpha.x;
    m.alpha_y = u_glint_alpha.y;
    m.rho = g_glint_slope_correlation;
    m.g2 = u_glint_g2;
    return m;
}

#ifdef GLINTLAB_GLINT_VIEW_DIFFERENTIALS
// The change per pixel step (x right, y down the image, as the footprint's)
// of the unit view direction towards u_eye and of the unit shading normal,
// in world space; glint_shade turns them into its frame (g_glint_view).
// Zero (a host that never sets them): no sweep, the model reads the pixel
// centre.
vec3 g_glint_dwo_dx = vec3(0.0f);
vec3 g_glint_dwo_dy = vec3(0.0f);
vec3 g_glint_dn_dx = vec3(0.0f);
vec3 g_glint_dn_dy = vec3(0.0f);

void glint_set_view_derivatives(vec3 dwo_dx, vec3 dwo_dy, vec3 dn_dx, vec3 dn_dy) {
    g_glint_dwo_dx = dwo_dx;
    g_glint_dwo_dy = dwo_dy;
    g_glint_dn_dx = dn_dx;
    g_glint_dn_dy = dn_dy;
}

// The same from the screen-space derivatives of the world position p and
// the unit shading normal n, as the forward pass takes them. Derivatives:
// call it at the top of main, in uniform control flow.
void glint_view_derivatives(vec3 p, vec3 n) {
    vec3 wo = normalize(u_eye - p);
    glint_set_view_derivatives(dFdxFine(wo), -dFdyFine(wo), dFdxFine(n), -dFdyFine(n));
}
#endif

// The pixel footprint in uv (ARCHITECTURE.md §3): uv derivatives per pixel
// step, x to the right and y DOWN the image (hence -dFdy in OpenGL window
// coordinates; fine derivatives as the renderer, dFdx/dFdy in GLSL ES). Derivatives are undefined
// in non-uniform control flow: call this at the top of main, before any branch on per-pixel data.
Footprint glint_footprint(vec2 uv) {
    Footprint fp;
    fp.uv = uv;
    fp.duvdx = dFdxFine(uv);
    fp.duvdy = -dFdyFine(uv);
    return fp;
}

// f(wo, wi) cos(theta_i) of the glint material, local frame (z the normal).
vec3 glint_eval(vec3 wo, vec3 wi, Footprint fp) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
    vec3 h = normalize(wo + wi);
    return glint_brdf(glint_material(), wo, wi, h, glint_ndf(h, fp)) * wi.z;
}

// Radiance towards u_eye from world point p with shading normal n, world
// dp/du and footprint fp; the frame of render/surface_bsdf.cpp (tangent along
// dp/du, two-sided).
vec3 glint_shade(vec3 p, vec3 n, vec3 dpdu, Footprint fp) {
    vec3 wo_world = normalize(u_eye - p);
    vec3 t = dpdu - n * dot(n, dpdu);
    float len = length(t);
    vec3 b;
    if (len > 1e-12f && !isinf(len) && !isnan(len)) {
        t = t / len;
        b = cross(n, t);
    } else {
        // Duff et al. 2017 orthonormal basis.
        float s = n.z >= 0.0f ? 1.0f : -1.0f;
        float a = -1.0f / (s + n.z);
        float c = n.x * n.y * a;
        t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
        b = vec3(c, s + n.y * n.y * a, -n.y);
    }
    bool back = dot(wo_world, n) < 0.0f;
    if (back) {
        n = -n;
        b = -b;
    }
    // Σ_xy changes sign in the flipped frame (core/slope_frame.glsl
    // slopes_in_shading_frame).
    g_glint_slope_correlation = back ? -g_glint_front_correlation : g_glint_front_correlation;
    if (g_glint_mean_slope != vec2(0.0f)) {
        // The normal map's mean normal (glint_set_inputs widened the lobe).
        vec2 mean = mean_slope_in_shading_frame(back, 1.0f, g_glint_mean_slope);
        mean = visible_slope(mean, vec3(dot(wo_world, t), dot(wo_world, b), dot(wo_world, n)));
        tilt_frame_to_slope(mean, t, b, n);
    }
    vec3 wo = vec3(dot(wo_world, t), dot(wo_world, b), dot(wo_world, n));
#ifdef GLINTLAB_GLINT_VIEW_DIFFERENTIALS
    // In the final frame, as the forward pass's.
    g_glint_view = view_differentials_in_frame(wo, g_glint_dwo_dx, g_glint_dwo_dy, g_glint_dn_dx,
                                               g_glint_dn_dy, t, b, n, back ? -1.0f : 1.0f);
#endif
    vec3 radiance = vec3(0.0f);
    // The point lights, then the directional lights, in one do-while loop:
    // SIMD back ends that run a block of pixels in lock-step (llvmpipe,
    // SwiftShader) run a loop's body once more after its last iteration, and
    // a loop of no iteration once, so two for loops over the light kinds
    // cost one or two glint evaluations more than there are lights (a third
    // of an llvmpipe frame under one light).
    int points = clamp(u_point_count, 0, GLINT_MAX_LIGHTS);
    int lights = points + clamp(u_directional_count, 0, GLINT_MAX_LIGHTS);
    if (lights > 0) {
        int k = 0;
        do {
            bool point = k < points;
            int i = point ? k : k - points;
            vec3 w;
            float r2 = 1.0f;
            if (point) {
                vec3 d = u_point_position[i] - p;
                r2 = dot(d, d);
                w = d * inversesqrt(r2);
            } else {
                w = u_directional_direction[i];
            }
            vec3 wi = vec3(dot(w, t), dot(w, b), dot(w, n));
            if (wi.z > 0.0f) {
#ifdef GLINTLAB_GLINT_OWN_LIGHTS
                vec3 irradiance = point ? u_point_intensity[i] / r2 : u_directional_irradiance[i];
                radiance += g_glint_color_input * glint_own_light_add(wo, wi, irradiance, fp);
#else
                vec3 f = glint_eval(wo, wi, fp);
                radiance += point ? f * u_point_intensity[i] / r2 : f * u_directional_irradiance[i];
#endif
            }
            ++k;
        } while (k < lights);
    }
#ifdef GLINTLAB_GLINT_OWN_LIGHTS
    radiance += g_glint_color_input * glint_own_lights_flush(wo, fp);
#endif
#ifdef GLINTLAB_GLINT_OWN_LIGHTS
    if (u_environment_on) radiance += g_glint_color_input * glint_own_environment(n, wo_world, fp);
#endif
#ifdef GLINTLAB_GLINT_SHADES_ENVIRONMENT
    if (u_environment_on) radiance += glint_environment(wo, t, b, n, g_glint_color_input, fp);
#endif
    // Non-finite results are dropped, as the renderers do.
    if (any(isnan(radiance)) || any(isinf(radiance))) radiance = vec3(0.0f);
    return radiance;
}

// The slope covariance (Σ_xx, Σ_yy, Σ_xy) over the pixel from the surface's
// own curvature (docs/MODELS.md, "Curved surfaces"): the unit normal's change
// per pixel step, in glint_shade's frame (t along dpdu), gives the slope's
// change g = −(t·∂n, b·∂n); over the pixel's uniform footprint its
// covariance is (g_x g_xᵀ + g_y g_yᵀ)/12. Zero on a flat surface.
// Derivatives: call it at the top of main, in uniform control flow; add it
// to the inputs' slope_variance and slope_covariance_xy (a host that does
// not want it leaves it out).
vec3 glint_curvature_slope_covariance(vec3 n, vec3 dpdu) {
    vec3 dndx = dFdxFine(n);
    vec3 dndy = -dFdyFine(n);
    vec3 t = dpdu - n * dot(n, dpdu);
    float len = length(t);
    if (!(len > 1e-12f) || isinf(len)) return vec3(0.0f);
    t = t / len;
    vec3 b = cross(n, t);
    return linear_slope_covariance(vec2(dot(t, dndx), dot(b, dndx)),
                                   vec2(dot(t, dndy), dot(b, dndy)));
}

void main() {
    Footprint fp = glint_footprint(v_uv);
    vec3 n = normalize(v_normal);
    vec3 curvature = glint_curvature_slope_covariance(n, v_dpdu);
#ifdef GLINTLAB_GLINT_VIEW_DIFFERENTIALS
    glint_view_derivatives(v_position, n);
#endif
    GlintInputs inputs = glint_inputs_from_textures(fp);
    if (u_glint_curvature != 0) {
        inputs.slope_variance += vec2(curvature.x, curvature.y);
        inputs.slope_covariance_xy += curvature.z;
    }
    glint_set_inputs(inputs);
    o_radiance = vec4(glint_shade(v_position, n, v_dpdu, fp), 1.0f);
}
