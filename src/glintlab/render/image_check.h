// The last check of a render before its image is written: every pixel must be
// finite. A NaN or Inf pixel is a defect of the shading code, and the error
// names its cause — the first bad pixel, the surface seen there and its
// material and glint model — instead of surfacing later as an image writer's
// failure on the output file.
#pragma once

#include <optional>
#include <string>

#include "glintlab/core/image.h"
#include "glintlab/scene/scene.h"

namespace glintlab {

// The first pixel (row-major) with a non-finite channel, if any.
struct BadPixel {
    int x = 0, y = 0;
    glm::vec3 value{0.0f};
};
std::optional<BadPixel> find_non_finite_pixel(const Image& image);

// What the camera ray through the centre of pixel (x, y) hits first, in words:
// "shape 'sphere', material 'glitter' (glint, model kneiphof2025)", or
// "no surface (the background / environment)".
std::string describe_pixel_surface(const Scene& scene, int x, int y);

// Throws glintlab::Error naming the first non-finite pixel and what it shows
// (`what` says which image: "render of scene.json").
void require_finite_image(const Scene& scene, const Image& image, const std::string& what);

}  // namespace glintlab
