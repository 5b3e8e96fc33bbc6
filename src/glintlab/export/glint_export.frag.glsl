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
//     vec3 glint_shade(vec3 p, vec3 n_geo, vec3 dpdu, Footprint fp);
//     vec3 glint_eval(vec3 wo, vec3 wi, Footprint fp);  // f(wo, wi) cos(wi)
#include "glintlab/core/constants.glsl"
#include "glintlab/core/footprint.glsl"
#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/glints/material.glsl"

const int GLINT_MAX_LIGHTS = 4;

in vec3 v_position;  // world position
in vec3 v_normal;    // world shading normal (normalized here)
in vec2 v_uv;        // the glint pattern's coordinates (its density is per unit uv area)
in vec3 v_dpdu;      // world dp/du: the tangent of the shading frame
out vec4 o_radiance;  // linear radiance, alpha 1

uniform vec3 u_eye;  // world camera position
// The glint material (GlintDesc, scene.h): colour, optional diffuse base
// under a dielectric coat, masking (GLINT_G2_*); its Fresnel u_fresnel_*
// (GLINT_FRESNEL_*) is declared in glint_uniforms.glsl.
uniform vec3 u_glint_color;
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

GlintMaterial glint_material() {
    GlintMaterial m;
    m.color = u_glint_color;
    m.base_albedo = u_glint_base_albedo;
    m.fresnel_mode = u_fresnel_mode;
    m.fresnel_f0 = u_fresnel_f0;
    m.fresnel_eta = u_fresnel_eta;
    m.fresnel_k = u_fresnel_k;
    m.ndf = u_glint_ndf;
    m.alpha_x = u_glint_alpha.x;
    m.alpha_y = u_glint_alpha.y;
    m.g2 = u_glint_g2;
    return m;
}

// The pixel footprint in uv (ARCHITECTURE.md §3): uv derivatives per pixel
// step, x to the right and y DOWN the image (hence -dFdy in OpenGL window
// coordinates; fine derivatives as the renderer, dFdx/dFdy in GLSL ES). Derivatives are undefined in non-uniform control flow: call
// this at the top of main, before any branch on per-pixel data.
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
    if (dot(wo_world, n) < 0.0f) {
        n = -n;
        b = -b;
    }
    vec3 wo = vec3(dot(wo_world, t), dot(wo_world, b), dot(wo_world, n));
    vec3 radiance = vec3(0.0f);
    for (int i = 0; i < GLINT_MAX_LIGHTS; ++i) {
        if (i >= u_point_count) break;
        vec3 d = u_point_position[i] - p;
        float r2 = dot(d, d);
        vec3 w = d * inversesqrt(r2);
        vec3 wi = vec3(dot(w, t), dot(w, b), dot(w, n));
        if (wi.z <= 0.0f) continue;
#ifdef GLINTLAB_GLINT_OWN_LIGHTS
        radiance += u_glint_color * glint_own_light(wo, wi, u_point_intensity[i] / r2, fp);
#else
        radiance += glint_eval(wo, wi, fp) * u_point_intensity[i] / r2;
#endif
    }
#ifdef GLINTLAB_GLINT_OWN_LIGHTS
    if (u_environment_on) radiance += u_glint_color * glint_own_environment(n, wo_world, fp);
#endif
#ifdef GLINTLAB_GLINT_SHADES_ENVIRONMENT
    if (u_environment_on) radiance += glint_environment(wo, t, b, n, u_glint_color, fp);
#endif
    for (int i = 0; i < GLINT_MAX_LIGHTS; ++i) {
        if (i >= u_directional_count) break;
        vec3 w = u_directional_direction[i];
        vec3 wi = vec3(dot(w, t), dot(w, b), dot(w, n));
        if (wi.z <= 0.0f) continue;
#ifdef GLINTLAB_GLINT_OWN_LIGHTS
        radiance += u_glint_color * glint_own_light(wo, wi, u_directional_irradiance[i], fp);
#else
        radiance += glint_eval(wo, wi, fp) * u_directional_irradiance[i];
#endif
    }
    // Non-finite results are dropped, as the renderers do.
    if (any(isnan(radiance)) || any(isinf(radiance))) radiance = vec3(0.0f);
    return radiance;
}

void main() {
    Footprint fp = glint_footprint(v_uv);
    o_radiance = vec4(glint_shade(v_position, normalize(v_normal), v_dpdu, fp), 1.0f);
}
