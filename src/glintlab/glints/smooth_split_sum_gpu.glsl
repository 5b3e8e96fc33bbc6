// GPU glue of the smooth glint material with the engine-standard
// image-based lighting (GPU option "split_sum_environment" of the smooth
// model, glints/smooth/smooth_gpu_hooks.cpp): D_P = D under point and
// directional lights as smooth_gpu.glsl, and under the environment ONE
// prefiltered-radiance lookup times the split-sum albedo (Karis 2013's split
// sum, the term 003 Eq. 11 calls L_o), as a real-time engine shades a smooth
// material, instead of the forward pass's multi-sample filtered importance
// sampling (the default, which follows the CPU reference). The maps are
// kneiphof2025's: its GGX-prefiltered radiance layers and its DFG table,
// bound through kneiphof2025.glsl's fetch functions. A Beckmann material
// reads them at its own alpha (engines keep one GGX-prefiltered map).
// Defines GLINTLAB_GLINT_SHADES_ENVIRONMENT, so the forward shader calls
// glint_environment for glint materials.
#ifndef GLINTLAB_GLINTS_SMOOTH_SPLIT_SUM_GPU_GLSL
#define GLINTLAB_GLINTS_SMOOTH_SPLIT_SUM_GPU_GLSL

#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/glints/kneiphof2025/kneiphof2025.glsl"
uniform vec3 u_kneiphof2025_f0;               // kneiphof2025_f0(desc): Schlick F0 of the Fresnel
uniform float u_kneiphof2025_radiance_scale;  // current environment scale / prefiltered one
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(D_Microfacet_correlated(u_glint_ndf, h, u_glint_alpha.x, u_glint_alpha.y,
                                        g_glint_slope_correlation));
}
#define GLINTLAB_GLINT_SHADES_ENVIRONMENT 1
// E_rho(wo) L_pre(r): wo local, (t, b, n) the world shading frame.
vec3 glint_environment(vec3 wo, vec3 t, vec3 b, vec3 n, vec3 color, Footprint fp) {
    if (wo.z <= 0.0f) return vec3(0.0f);
    vec3 wr = (-wo.x) * t + (-wo.y) * b + wo.z * n;
    // Isotropic maps: the geometric mean of an anisotropic alpha.
    float alpha = clamp(sqrt(u_glint_alpha.x * u_glint_alpha.y), 1e-4f, 1.0f);
    float roughness = sqrt(alpha);
    vec3 dfg = kneiphof2025_dfg_fetch(wo.z, roughness);
    vec3 e_rho = color * (u_kneiphof2025_f0 * dfg.x + vec3(dfg.y));
    return u_kneiphof2025_radiance_scale * e_rho *
           kneiphof2025_radiance_fetch(kneiphof2025_lookup_direction(n, wr, alpha), roughness);
}

#endif
