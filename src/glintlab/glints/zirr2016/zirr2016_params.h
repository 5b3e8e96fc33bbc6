// Parameters of the zirr2016 glint model (its block "zirr2016": {...} of a
// glint material; ranges and defaults justified in docs/MODELS.md).
#pragma once

namespace glintlab {

struct Zirr2016Params {
    // R of 000 Eq. 4 in (0, 1]: success probability R D(h) / D(n), and the
    // width of the angular cells in slope units (the micro-roughness).
    float microfacet_roughness = 0.025f;
    // Largest footprint ratio marched (000 §7: x16 in [ZK16]); beyond it the
    // footprint is widened isotropically. [1, 64].
    float max_anisotropy = 16.0f;
    // Texel width in footprint minor widths (LOD = log2(minor x S)), [0.5, 8].
    float screen_space_scale = 1.0f;
};

}  // namespace glintlab
