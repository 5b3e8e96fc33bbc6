// The footprint contract (ARCHITECTURE.md §3): every glint model receives the
// pixel footprint in uv space. The CPU renderer fills it from ray
// differentials (pbrt-v4 ComputeDifferentials), the GPU renderer from
// dFdx/dFdy of the interpolated uv.
#ifndef GLINTLAB_CORE_FOOTPRINT_GLSL
#define GLINTLAB_CORE_FOOTPRINT_GLSL

struct Footprint {
    vec2 uv;     // uv at the pixel centre
    vec2 duvdx;  // change of uv for one pixel step in x
    vec2 duvdy;  // change of uv for one pixel step in y
};

#endif
