// Parameters of the kneiphof2025 glint model (its block "kneiphof2025": {...}
// of a glint material; ranges and defaults justified in docs/MODELS.md).
#pragma once

namespace glintlab {

struct Kneiphof2025Params {
    enum class Variant { Kneiphof2025, Wang2020Style };
    // K radiance levels of the environment partition (003 §4-5): 4 or 8.
    int levels = 8;
    // l of 003 §5: the dimmest non-zero level is at least this luminance
    // (the paper suggests [1e-5, 1e-2]; we accept [1e-8, 1]).
    float black_level = 1e-2f;
    // 003 Fig. 8: "kneiphof2025" (p from the environment's partition) or
    // "wang2020_style" (p from a fixed cone of half-angle gamma_deg).
    Variant variant = Variant::Kneiphof2025;
    float gamma_deg = 5.0f;
    // The Gaussian of the dual-gated law: "conditional" (default: the
    // interior case's exact moments, binomial_dual_gated_conditional) or
    // "algorithm1" (003 as published, mean 1 + (N - 2) p, which overestimates
    // E[b] by up to ~20 % where N p ~ 1-10; docs/VALIDATION.md). Like
    // deliot2023's original_defects, the published form is an option.
    bool conditional_gaussian = true;
    // The smooth radiance the glint factor multiplies (Eq. 11), docs/MODELS.md:
    // "lobe_sun" (default; ours): the reflection lobe of wo by 32 filtered
    // importance samples of the maps without the environment's bright
    // sources (Kneiphof2025Sources), plus the sources by the BRDF at 16
    // directions inside them; within 5.3 % of the exact integral on every
    // blender-data map, sphere and grazing plane (docs/VALIDATION.md).
    // "as_published" (alias "split_sum"): 003's split sum, one prefiltered
    // lookup whose kernel assumes n = v = r; up to +46 % (+74 % on the rim)
    // under a low sun. "lobe": the lobe with the sources left in the maps,
    // up to +14 % under a low sun and +297 % on a grazing plane under
    // studio lamps.
    enum class Smooth { Lobe, SplitSum, LobeSun };
    Smooth smooth = Smooth::LobeSun;
    // Reused deliot2023 grid parameters (000; see Deliot2023Params): R for the
    // angular grid of point / directional / sphere lights, the minimum glint
    // size in pixels, and the per-cell log-density jitter.
    float microfacet_roughness = 0.025f;
    // "area_grid": the angular cell size of sphere lights' and sun cones'
    // glints: "light_size" (default, ours: R widened by the light's
    // half-vector cone, so glints live as long as an explicit facet stays
    // in the light's reflection) or "as_published" (R, as for a point light).
    // kneiphof2025.glsl kneiphof2025_area_grid_roughness; docs/MODELS.md.
    bool light_sized_area_grid = true;
    float screen_space_scale = 1.5f;
    float density_randomization = 0.0f;
};

}  // namespace glintlab
