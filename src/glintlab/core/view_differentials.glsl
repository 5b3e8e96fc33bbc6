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

#endif
