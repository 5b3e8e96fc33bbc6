// The view's and the surface normal's change across a pixel, in the local
// shading frame (t, b, n): what a glint model needs to know how far the half
// vector sweeps over the pixel (Chermain et al. 2021, "Real-Time Geometric
// Glint Anti-Aliasing with Normal Map Filtering", I3D 2021, §4: the
// derivatives of the half vector's slope). The CPU renderer fills it from
// ray differentials and the hit's ∂n/∂(u, v) (render/surface_bsdf.cpp), the
// forward pass from dFdx/dFdy of the view direction and the interpolated
// normal (realtime/shaders/forward.frag.glsl).
#ifndef GLINTLAB_CORE_VIEW_DIFFERENTIALS_GLSL
#define GLINTLAB_CORE_VIEW_DIFFERENTIALS_GLSL

struct ViewDifferentials {
    vec3 wo;     // the unit view direction at the pixel centre
    vec3 wo_dx;  // change of the world view direction per pixel step in x, local coordinates
    vec3 wo_dy;  // ... in y (down the image, as the footprint's)
    vec2 n_dx;   // change of the unit normal per pixel step in x: its t and b components
    vec2 n_dy;
};

#ifndef GLINTLAB_CPP
// The GPU passes' form (forward pass, export): from the world-space change
// per pixel step of the view direction (dwo_dx, dwo_dy) and of the unit
// shading normal (dn_dx, dn_dy), in the final shading frame (t, b, n); `wo`
// already in it; flip −1 where the frame was flipped to the back side (the
// normal's change is negated with it, as render/surface_bsdf.cpp's
// view_differentials does on the CPU).
ViewDifferentials view_differentials_in_frame(vec3 wo, vec3 dwo_dx, vec3 dwo_dy, vec3 dn_dx,
                                              vec3 dn_dy, vec3 t, vec3 b, vec3 n, float flip) {
    ViewDifferentials v;
    v.wo = wo;
    v.wo_dx = vec3(dot(dwo_dx, t), dot(dwo_dx, b), dot(dwo_dx, n));
    v.wo_dy = vec3(dot(dwo_dy, t), dot(dwo_dy, b), dot(dwo_dy, n));
    v.n_dx = flip * vec2(dot(dn_dx, t), dot(dn_dx, b));
    v.n_dy = flip * vec2(dot(dn_dy, t), dot(dn_dy, b));
    return v;
}
#endif

#endif
