// The BRDF values of the non-glint materials (microfacet/bxdfs.h), shared by
// the CPU BxDFs (microfacet/bxdfs.cpp) and the GPU forward pass
// (glints/material.glsl eval_bsdf). Local frame (z = shading normal); the
// callers check that wo and wi lie on the same side and that the lobe is not
// a delta (microfacet_effectively_smooth), sampling and pdfs stay in C++.
// Microfacet reflection is Cook & Torrance 1982 / Walter et al. 2007 Eq. 20:
//     f = D(wm) G2(wo, wi) F(wo.wm) / (4 |cos_o| |cos_i|),
// D and G2 the anisotropic NDF with height-correlated Smith masking.
#ifndef GLINTLAB_MICROFACET_BXDFS_GLSL
#define GLINTLAB_MICROFACET_BXDFS_GLSL

#include "glintlab/core/constants.glsl"
#include "glintlab/microfacet/fresnel.glsl"
#include "glintlab/microfacet/masking.glsl"
#include "glintlab/microfacet/ndf.glsl"

// Below this roughness a lobe is a delta (MicrofacetDistribution::
// effectively_smooth, kSmoothAlpha of microfacet/bxdfs.h).
bool microfacet_effectively_smooth(float alpha_x, float alpha_y) {
    return max(alpha_x, alpha_y) < 1e-3f;
}

// A half vector on the +z side.
vec3 microfacet_face_up(vec3 n) {
    return n.z < 0.0f ? -n : n;
}

// D(wm) G2(wo, wi) of the distribution (MicrofacetDistribution::D, ::G2).
float microfacet_dg(int ndf, float alpha_x, float alpha_y, vec3 wo, vec3 wi, vec3 wm) {
    return D_Microfacet(ndf, wm, alpha_x, alpha_y) *
           G2_SmithCorrelated(ndf, wo, wi, alpha_x, alpha_y);
}

// Lambertian reflection (DiffuseBxdf).
vec3 diffuse_f(vec3 albedo) {
    return albedo * INV_PI;
}

// Rough conductor (ConductorBxdf), complex IOR eta + i k per channel.
vec3 conductor_f(int ndf, float alpha_x, float alpha_y, vec3 eta, vec3 k, vec3 wo, vec3 wi) {
    float cos_o = abs(wo.z);
    float cos_i = abs(wi.z);
    if (cos_o == 0.0f || cos_i == 0.0f) return vec3(0.0f);
    vec3 wm = wi + wo;
    if (dot(wm, wm) == 0.0f) return vec3(0.0f);
    wm = microfacet_face_up(normalize(wm));
    vec3 F = F_Conductor(abs(dot(wo, wm)), eta, k);
    return microfacet_dg(ndf, alpha_x, alpha_y, wo, wi, wm) * F / (4.0f * cos_o * cos_i);
}

// The reflection lobe of a rough dielectric interface (DielectricBxdf), wm
// the half vector on the +z side; the transmission lobe stays in C++ (the
// GPU forward pass shades reflection only).
float dielectric_reflection_f(int ndf, float alpha_x, float alpha_y, float eta, vec3 wo, vec3 wi,
                              vec3 wm) {
    float F = F_Dielectric(dot(wo, wm), eta);
    float DG = microfacet_dg(ndf, alpha_x, alpha_y, wo, wi, wm);
    return DG * F / abs(4.0f * wi.z * wo.z);
}

// Plastic (PlasticBxdf): a Lambertian base under a dielectric coat of IOR
// eta, f = diffuse / pi (1 - F(cos_o)) (1 - F(cos_i)) + the coat's microfacet
// reflection (none when the coat is smooth: its delta lobe is sampled apart).
vec3 plastic_f(vec3 diffuse, float eta, int ndf, float alpha_x, float alpha_y, vec3 wo, vec3 wi) {
    float cos_o = abs(wo.z);
    float cos_i = abs(wi.z);
    if (cos_o == 0.0f || cos_i == 0.0f) return vec3(0.0f);
    float Fo = F_Dielectric(cos_o, eta);
    float Fi = F_Dielectric(cos_i, eta);
    vec3 result = diffuse * INV_PI * (1.0f - Fo) * (1.0f - Fi);
    if (!microfacet_effectively_smooth(alpha_x, alpha_y)) {
        vec3 wm = microfacet_face_up(normalize(wo + wi));
        float F = F_Dielectric(abs(dot(wo, wm)), eta);
        result += vec3(microfacet_dg(ndf, alpha_x, alpha_y, wo, wi, wm) * F / (4.0f * cos_o * cos_i));
    }
    return result;
}

// A rough metal whose Fresnel term is Schlick's with F0 = `f0` (glTF 2.0's
// conductor_fresnel, Khronos glTF 2.0 specification Appendix B.3.3).
vec3 schlick_metal_f(vec3 f0, int ndf, float alpha_x, float alpha_y, vec3 wo, vec3 wi) {
    float cos_o = abs(wo.z);
    float cos_i = abs(wi.z);
    if (cos_o == 0.0f || cos_i == 0.0f || microfacet_effectively_smooth(alpha_x, alpha_y))
        return vec3(0.0f);
    vec3 wm = wi + wo;
    if (dot(wm, wm) == 0.0f) return vec3(0.0f);
    wm = microfacet_face_up(normalize(wm));
    vec3 F = F_Schlick(f0, abs(dot(wo, wm)));
    return microfacet_dg(ndf, alpha_x, alpha_y, wo, wi, wm) * F / (4.0f * cos_o * cos_i);
}

// glTF 2.0's metallic-roughness material (MetallicRoughnessBxdf; Appendix
// B.3.5): mix(dielectric, metal, metallic). The dielectric is plastic_f
// (a Lambertian of base_color under a coat of IOR eta), the metal
// schlick_metal_f with F0 = base_color; both share one distribution.
vec3 metallic_roughness_f(vec3 base_color, float metallic, float eta, int ndf, float alpha_x,
                          float alpha_y, vec3 wo, vec3 wi) {
    vec3 dielectric = plastic_f(base_color, eta, ndf, alpha_x, alpha_y, wo, wi);
    vec3 metal = schlick_metal_f(base_color, ndf, alpha_x, alpha_y, wo, wi);
    return (1.0f - metallic) * dielectric + metallic * metal;
}

#endif
