// Parameters of the wang2020 glint model (its block "wang2020": {...} of a
// glint material; ranges in docs/MODELS.md, section wang2020). The particle
// density is the material's log_density (N = round(e^log_density) particles
// per unit uv tile, the explicit ground truth's convention), the roughness its
// isotropic Beckmann alpha.
#pragma once

#include <cstdint>

namespace glintlab {

struct Wang2020Params {
    double gamma_deg = 1.0;             // search cone half-angle γ (001 §3.1), [1, 30]
    int depth = 11;                     // quadtree depth (001 §6), [1, 16]
    int dpf_theta = 90;                 // DPF table θi and θo resolution (Table 2), [2, 180]
    int dpf_phi = 180;                  // DPF table Δφ resolution (Table 2), [2, 360]
    int prefilter_samples = 64;         // K of Eq. 16, [1, 4096]
    bool directional_occlusion = true;  // §4.4: one mirror-direction visibility ray
    bool blur = true;                   // §4.4: the two Gaussian blurs (9 and 3 taps) in renders
    // "micro": "per_particle" (default: each particle reflects the γ-cone
    // averaged environment about its own hashed Beckmann normal; blended
    // scale transitions) or "as_published" (Eq. 20: accept iff λ < P̂, weight
    // 1/P̂; hard thresholds at 4 and 64). docs/MODELS.md, wang2020.
    bool micro_per_particle = true;
    // "prefilter": "mis" (default: K BRDF + K environment samples per texel,
    // balance heuristic) or "as_published" (Eq. 16: K BRDF samples).
    bool prefilter_mis = true;
    // "dpf_roughness": "exact" (default: the DPF table of the material's own
    // α) or "as_published" (§4.4: linear in α between the two bracketing
    // tables of 0.02, 0.04, 0.1, 0.2, 0.4, 0.6, 0.8, 1). docs/MODELS.md.
    bool dpf_exact_roughness = true;
    // "scale_count": "effective" (default: with "micro": "per_particle", the
    // scales are chosen by the footprint's effective particle count n r, r =
    // P under lights, E[f]²/E[f²] under the environment, so the micro scale
    // sparkles wherever the ground truth does; at most 4096 particles
    // enumerated) or "particles" (001 §4.3: the particle count n).
    bool scale_count_effective = true;
    // "particle_radiance": "point" (default: with "micro": "per_particle",
    // each particle reflects the environment's value in its mirror direction,
    // as an explicit facet does) or "cone" (the γ-cone average L_γ).
    bool particle_radiance_point = true;
    // "glint_blur" (with "blur" on; the 9-tap blur of the directional
    // occlusion always runs): "auto" (default: §4.4's 3-tap Gaussian blur of
    // the glint layer where the image takes one sample per pixel, the GPU
    // and a CPU render at 1 spp, none where the CPU supersamples, whose
    // jittered footprints already filter the sparkle as the ground truth's
    // do), "none" or "as_published" (always the 3-tap blur). One kernel per
    // image: the wang2020 materials of a scene with "blur" on must agree
    // (wang2020_glint_blur_taps).
    enum class GlintBlur { Auto, None, AsPublished };
    GlintBlur glint_blur = GlintBlur::Auto;
};

}  // namespace glintlab
