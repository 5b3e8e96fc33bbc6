// The glint material's Fresnel (FresnelDesc, scene's "fresnel" block) as a
// function of its mode, shared by material.glsl's glint_fresnel and the
// models that put F inside their own integrals (wang2020's M, 001 Eq. 11).
#ifndef GLINTLAB_GLINTS_GLINT_FRESNEL_GLSL
#define GLINTLAB_GLINTS_GLINT_FRESNEL_GLSL

#include "glintlab/microfacet/fresnel.glsl"

// FresnelDesc::Mode (scene.h), in its order.
const int GLINT_FRESNEL_NONE = 0;
const int GLINT_FRESNEL_SCHLICK = 1;
const int GLINT_FRESNEL_CONDUCTOR = 2;
const int GLINT_FRESNEL_DIELECTRIC = 3;

// F(cos) for mode: Schlick (f0), conductor (eta + i k per channel),
// dielectric (eta.x); 1 for none.
vec3 glint_fresnel_mode(int mode, vec3 f0, vec3 eta, vec3 k, float cos_oh) {
    if (mode == GLINT_FRESNEL_SCHLICK) return F_Schlick(f0, cos_oh);
    if (mode == GLINT_FRESNEL_CONDUCTOR) return F_Conductor(cos_oh, eta, k);
    if (mode == GLINT_FRESNEL_DIELECTRIC) return vec3(F_Dielectric(cos_oh, eta.x));
    return vec3(1.0f);
}

#endif  // GLINTLAB_GLINTS_GLINT_FRESNEL_GLSL
