// The half vector's slope sweep across a pixel (Chermain et al. 2021, §4:
// the derivatives of the half vector's slope that set the filter of their
// geometric glint anti-aliasing), from the view differentials of
// core/view_differentials.glsl.
#ifndef GLINTLAB_CORE_HALF_SLOPE_DIFFERENTIALS_GLSL
#define GLINTLAB_CORE_HALF_SLOPE_DIFFERENTIALS_GLSL

#include "glintlab/core/view_differentials.glsl"

// d(slope of h) for one pixel step, with the light's direction held fixed in
// world space (exact for directional and environment light; a point light's
// own parallax over the pixel, |∂p| / distance, is left out). Slopes follow
// the microfacet convention s = −(h_t, h_b) / h_n. H = wo + wi = 2 (wo·h) h
// in the local frame; as the frame turns with the normal by ∂n (∂n ⊥ n), a
// world-fixed vector v changes its local coordinates by
// (−∂n_t v_n, −∂n_b v_n, ∂n_t v_t + ∂n_b v_b), and wo also by ∂wo.
vec2 half_slope_differential(vec3 H, vec3 dwo, vec2 dn) {
    vec3 dH = vec3(dwo.x - dn.x * H.z, dwo.y - dn.y * H.z, dwo.z + dn.x * H.x + dn.y * H.y);
    float inv_z = 1.0f / H.z;
    return vec2(-(dH.x - H.x * inv_z * dH.z) * inv_z, -(dH.y - H.y * inv_z * dH.z) * inv_z);
}

// (∂s/∂x, ∂s/∂y) of the half vector h (unit, local frame, h.z > 0).
vec4 half_slope_differentials(vec3 h, ViewDifferentials v) {
    vec3 H = (2.0f * dot(v.wo, h)) * h;
    if (!(H.z > 0.0f)) return vec4(0.0f);
    vec2 dx = half_slope_differential(H, v.wo_dx, v.n_dx);
    vec2 dy = half_slope_differential(H, v.wo_dy, v.n_dy);
    return vec4(dx.x, dx.y, dy.x, dy.y);
}


#endif
