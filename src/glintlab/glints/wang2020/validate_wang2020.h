// `glintlab validate wang2020`: the prefiltered discrete stochastic
// microfacet model of 001 against the explicit ground truth, the white
// furnace, the Table 1 average glint energy and the memory of every table.
// Checks and their domains: docs/VALIDATION.md, section "wang2020".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "glintlab/validate/report.h"

namespace glintlab {

struct Wang2020ValidationOptions {
    uint64_t seed = 1;
    // 003 Fig. 6 protocol: a sphere (orthographic, view +z) under each map.
    std::vector<std::string> environment_maps = {
        "/usr/share/blender/datafiles/studiolights/world/forest.exr",
        "/usr/share/blender/datafiles/studiolights/world/city.exr",
        "/usr/share/blender/datafiles/studiolights/world/studio.exr"};
    int image_size = 40;    // sphere image resolution (pixels per side)
    int realizations = 16;  // per image, both models (for mean and variance)
    int furnace_realizations = 256;
    uint64_t quadtree_particles = 1000000;  // memory check (depth 11)
    // The block's "micro" and "prefilter" modes (docs/MODELS.md, wang2020):
    // false reproduces the printed method (and the suite's earlier numbers).
    bool micro_per_particle = true;
    bool prefilter_mis = true;
    // Prefilter table of the ground-truth rows (θn, φn, θo, φo); the default
    // is Table 2's α = 0.1 resolution (docs/VALIDATION.md, wang2020).
    int prefilter_res[4] = {31, 60, 10, 36};
};

ValidationReport validate_wang2020(const Wang2020ValidationOptions& options);

}  // namespace glintlab
