// The surface shading around the glint kernels, one source for the CPU
// (glints/glint_bxdf.cpp includes it through core/glsl.h) and the GPU forward
// pass (realtime/shaders/forward.frag.glsl). The glint material's BRDF
// (ARCHITECTURE.md "Materials and the glint material";
// 000 Eq. 1-3, 002 Eq. 2, 004 Eq. 1):
//     f(wo, wi) = color · F(wo·h) · G2(wo, wi) · D_P(h) / (4 |wo·n| |wi·n|)
//               + base_albedo / π · (1 − F_c(cos_o)) (1 − F_c(cos_i)),
// F the material's Fresnel (none, Schlick, conductor, dielectric), G2 the
// model's masking, D_P(h) the model's footprint NDF (computed by the caller:
// the C++ switch of GlintBxdf::footprint_ndf, the GPU glue's glint_ndf), and
// the optional diffuse base (002 Fig. 7) under a dielectric coat of IOR
// F_c = F_Dielectric(·, fresnel_eta.x): the plastic layering of
// microfacet/bxdfs.glsl with the glint lobe as its coat.
// The non-glint materials' BRDFs come from microfacet/bxdfs.glsl; eval_bsdf
// below is the GPU forward pass's dispatch over all of them.
#ifndef GLINTLAB_GLINTS_MATERIAL_GLSL
#define GLINTLAB_GLINTS_MATERIAL_GLSL

#include "glintlab/core/constants.glsl"
#include "glintlab/microfacet/bxdfs.glsl"
#include "glintlab/glints/glint_fresnel.glsl"
#include "glintlab/microfacet/fresnel.glsl"
#include "glintlab/microfacet/masking.glsl"
#include "glintlab/microfacet/ndf.glsl"

// The material's masking-shadowing (glint_g2_mode in glint_bxdf.h): the
// height-correlated Smith G2 of the smooth NDF, or the V-cavity G2 that
// chermain2020 takes as published (004 Eq. 14-16; its "masking" key).
const int GLINT_G2_SMITH_CORRELATED = 0;
const int GLINT_G2_VCAVITY = 1;

// GlintDesc's shading parameters (scene.h).
struct GlintMaterial {
    vec3 color;
    vec3 base_albedo;  // (0, 0, 0): no diffuse base
    int fresnel_mode;  // GLINT_FRESNEL_*
    vec3 fresnel_f0;   // Schlick
    vec3 fresnel_eta;  // conductor (per channel), dielectric and coat (x)
    vec3 fresnel_k;    // conductor
    int ndf;           // NDF_BECKMANN / NDF_GGX of the smooth limit
    float alpha_x;
    float alpha_y;
    float rho;  // the slopes' correlation (D_Microfacet_correlated; 0 for most)
    int g2;     // GLINT_G2_*
};

vec3 glint_fresnel(GlintMaterial m, float cos_oh) {
    return glint_fresnel_mode(m.fresnel_mode, m.fresnel_f0, m.fresnel_eta, m.fresnel_k, cos_oh);
}

float glint_g2(GlintMaterial m, vec3 wo, vec3 wi, vec3 h) {
    if (m.g2 == GLINT_G2_VCAVITY) return G2_VCavity(wo, wi, h);
    return G2_SmithCorrelated_sheared(m.ndf, wo, wi, m.alpha_x, m.alpha_y, m.rho);
}

bool glint_has_base(GlintMaterial m) {
    return m.base_albedo != vec3(0.0f);
}

// The diffuse base's term (0 without a base or below the surface).
vec3 glint_base_f(GlintMaterial m, vec3 wo, vec3 wi) {
    if (!glint_has_base(m) || wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
    float eta = m.fresnel_eta.x;
    float fo = F_Dielectric(wo.z, eta);
    float fi = F_Dielectric(wi.z, eta);
    return m.base_albedo * (INV_PI * (1.0f - fo) * (1.0f - fi));
}

// The glint lobe's selection probability in sampling, PlasticBxdf's
// F(cos_o) / (F(cos_o) + (1 − F(cos_o)) max(base)); 1 without a base.
float glint_lobe_probability(GlintMaterial m, vec3 wo) {
    if (!glint_has_base(m)) return 1.0f;
    float fo = F_Dielectric(abs(wo.z), m.fresnel_eta.x);
    vec3 a = m.base_albedo;
    float wd = (1.0f - fo) * max(a.x, max(a.y, a.z));
    return fo + wd > 0.0f ? fo / (fo + wd) : 1.0f;
}

// f(wo, wi) for wo, wi above the surface, h = normalize(wo + wi) and
// d_p = D_P(h) per channel (the smooth D without a footprint).
vec3 glint_brdf(GlintMaterial m, vec3 wo, vec3 wi, vec3 h, vec3 d_p) {
    float g = glint_g2(m, wo, wi, h);
    return m.color * glint_fresnel(m, dot(wo, h)) * d_p * (g / (4.0f * wo.z * wi.z)) +
           glint_base_f(m, wo, wi);
}

#ifdef GLINTLAB_GLSL
#include "glintlab/core/footprint.glsl"

// Defined by the model's GPU glue (glints/**/*_gpu.glsl): D_P(h) over the
// pixel footprint, per channel.
vec3 glint_ndf(vec3 h, Footprint fp);

// The GPU forward pass's material (uniforms of realtime/gpu_renderer.cpp).
const int MATERIAL_DIFFUSE = 0;  // GpuMaterialType of realtime/forward_shaders.h
const int MATERIAL_CONDUCTOR = 1;
const int MATERIAL_DIELECTRIC = 2;
const int MATERIAL_PLASTIC = 3;
const int MATERIAL_GLINT = 4;
const int MATERIAL_METALLIC_ROUGHNESS = 5;

struct SurfaceMaterial {
    int type;     // MATERIAL_*
    vec3 albedo;     // diffuse, plastic, metallic-roughness (base colour)
    float metallic;  // metallic-roughness
    int ndf;         // conductor, dielectric, plastic, metallic-roughness
    float alpha_x;
    float alpha_y;
    vec3 eta;
    vec3 k;
    GlintMaterial glint;  // MATERIAL_GLINT
};

// f(wo, wi) without the cosine, local frame, for the forward pass: the CPU's
// BxDFs (render/surface_bsdf.cpp) through the same functions, the dielectric
// by its reflection only. D_P comes from the model's GPU glue, which defines
// vec3 glint_ndf(vec3 h, Footprint fp) ahead of this file.
vec3 eval_bsdf(SurfaceMaterial s, vec3 wo, vec3 wi, Footprint fp) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
    if (s.type == MATERIAL_DIFFUSE) return diffuse_f(s.albedo);
    vec3 h = normalize(wo + wi);
    if (s.type == MATERIAL_GLINT) return glint_brdf(s.glint, wo, wi, h, glint_ndf(h, fp));
    if (s.type == MATERIAL_PLASTIC)
        return plastic_f(s.albedo, s.eta.x, s.ndf, s.alpha_x, s.alpha_y, wo, wi);
    if (s.type == MATERIAL_METALLIC_ROUGHNESS)
        return metallic_roughness_f(s.albedo, s.metallic, s.eta.x, s.ndf, s.alpha_x, s.alpha_y, wo,
                                    wi);
    if (microfacet_effectively_smooth(s.alpha_x, s.alpha_y)) return vec3(0.0f);  // a delta lobe
    if (s.type == MATERIAL_CONDUCTOR)
        return conductor_f(s.ndf, s.alpha_x, s.alpha_y, s.eta, s.k, wo, wi);
    return vec3(dielectric_reflection_f(s.ndf, s.alpha_x, s.alpha_y, s.eta.x, wo, wi, h));
}
#endif

#endif
