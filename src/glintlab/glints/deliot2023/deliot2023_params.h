// Parameters of the deliot2023 glint model (its block "deliot2023": {...} of a
// glint material; ranges and defaults justified in docs/MODELS.md).
#pragma once

namespace glintlab {

struct Deliot2023Params {
    // R of 000 Eq. 4, in (0, 1]: fraction of D(n) a facet reflects; behaves like
    // a micro-roughness (smaller: fewer, brighter glints). Authors' values 0.015-0.036.
    float microfacet_roughness = 0.025f;
    // Minimum glint size in pixels (LOD = log2(minor axis * S / 2)); 1 aliases.
    float screen_space_scale = 1.5f;
    // Std-dev of the per-cell jitter of the log density, [0, 50].
    float density_randomization = 0.0f;
    // Reproduce the original HLSL's defects (docs/MODELS.md) for comparisons.
    bool original_defects = false;
    // "gaussian": the count's law. true ("conditional", default): Law 5b of
    // counting/binomial_laws.glsl, unbiased (E = N p); false ("single_gated"):
    // 003 Eq. 23 as published, +10-31 % at N p ~ 0.1-10. original_defects
    // overrides both with the authors' Eq. 16-18.
    bool conditional_gaussian = true;
};

}  // namespace glintlab
