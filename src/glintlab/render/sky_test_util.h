// A small sky for environment tests that need a sharp source: a 64 × 32
// lat-long gradient (blue-white towards the zenith) with a 2 × 2-texel
// sun of radiance 400 about 30° above the horizon, so kneiphof2025's
// prefilter takes it out as a source and a widened lobe visibly changes
// its highlight.
#pragma once

#include <filesystem>

#include "glintlab/core/image.h"

namespace glintlab::testing {

inline void write_sky_with_sun(const std::filesystem::path& path) {
    Image sky(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            const float up = 1.0f - float(y) / 31.0f;
            sky.at(x, y) = glm::vec3(0.2f + 0.6f * up, 0.3f + 0.6f * up, 0.5f + 0.5f * up);
            if (y >= 10 && y < 12 && x >= 30 && x < 32) sky.at(x, y) = glm::vec3(400.0f);
        }
    write_exr(sky, path);
}

}  // namespace glintlab::testing
