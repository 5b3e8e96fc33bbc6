// `glintlab validate kneiphof2025`: ground-truth comparison (003 Fig. 6
// protocol), white furnace (003 Fig. 7), the N < 1 and small-p regressions
// (003 Fig. 13-14). Checks and their domains: docs/VALIDATION.md, section
// "kneiphof2025".
#pragma once

#include <cstdint>
#include <filesystem>

#include "glintlab/validate/report.h"

namespace glintlab {

struct Kneiphof2025ValidationOptions {
    uint64_t seed = 1;
    int resolution = 64;             // sphere images, pixels per side
    int furnace_realizations = 256;  // 003 Fig. 7: averages of >= 256 realizations
    std::filesystem::path grid_png = "out/kneiphof2025_grid.png";  // comparison grid; empty: none
};

ValidationReport validate_kneiphof2025(const Kneiphof2025ValidationOptions& options);

}  // namespace glintlab
