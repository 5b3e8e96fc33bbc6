// A sub-footprint: one cell of a grid over the pixel footprint, shared by
// the CPU renderer (core/normal_map.cpp) and the forward pass
// (realtime/shaders/normal_map.glsl).
#ifndef GLINTLAB_CORE_FOOTPRINT_CELL_GLSL
#define GLINTLAB_CORE_FOOTPRINT_CELL_GLSL

#include "glintlab/core/footprint.glsl"

// Cell `cell` (x fastest) of the k × k grid that tiles the footprint's
// parallelogram {uv + a duvdx + b duvdy : a, b in [−½, ½]}: its centre, and
// the axes divided by k (a normal map's "lean_mixture", core/normal_map.h).
Footprint footprint_cell(Footprint fp, int cell, int k) {
    float kf = float(k);
    float a = (float(cell % k) + 0.5f) / kf - 0.5f;
    float b = (float(cell / k) + 0.5f) / kf - 0.5f;
    Footprint sub;
    sub.uv = fp.uv + a * fp.duvdx + b * fp.duvdy;
    sub.duvdx = fp.duvdx / kf;
    sub.duvdy = fp.duvdy / kf;
    return sub;
}

#endif
