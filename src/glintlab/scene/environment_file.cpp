#include "glintlab/scene/environment_file.h"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>
#include <glm/glm.hpp>

#include "glintlab/core/error.h"

namespace glintlab {

Image read_environment_image(const std::filesystem::path& path, float scale,
                             size_t* negative_texels) {
    Image image = read_image(path);
    size_t negatives = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            glm::vec3& p = image.at(x, y);
            const double m = std::max({p.x, p.y, p.z});
            const double limit = kMaxEnvironmentRadiance;
            if (m > limit || m * scale > limit)
                fail(
                    "{}: environment texel (x={}, y={}) = ({}, {}, {}) times scale {} exceeds the "
                    "limit {:g} on environment radiance (larger values overflow single-precision "
                    "sums); rescale the image",
                    path.string(), x, y, p.x, p.y, p.z, scale, kMaxEnvironmentRadiance);
            if (p.x < 0.0f || p.y < 0.0f || p.z < 0.0f) {
                ++negatives;
                p = glm::max(p, glm::vec3(0.0f));
            }
        }
    if (negatives > 0)
        fmt::print(stderr,
                   "warning: {}: {} environment texel{} with negative components clamped to 0\n",
                   path.string(), negatives, negatives == 1 ? "" : "s");
    if (negative_texels) *negative_texels = negatives;
    return image;
}

}  // namespace glintlab
