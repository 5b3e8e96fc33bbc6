// Post-process of 001 §4.4 ("Gaussian Blurring") on a glint buffer whose rgb
// holds the glint radiance and whose 4th channel holds the directional
// occlusion (visibility 0/1 of one ray along the mirror direction of o about
// n, §4.4 "Directional Occlusion"):
//   δ = G9 * visibility,  out = G3 * (rgb · δ).
// Kernel "size" k is the tap count (k × k, separable); σ = k / 6 so that ±3σ
// spans the kernel (the paper gives sizes only). Borders clamp to the edge.
// This is a standalone image-space pass: the CPU renderer has no per-model
// post-process hook (render/ is not ours), so callers apply it to a buffer.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace glintlab::wang2020 {

struct GlintBuffer {
    int width = 0, height = 0;
    std::vector<glm::vec4> texels;  // row-major, rgb = glints, w = visibility
};

// Separable normalised Gaussian blur of one channel set (size odd, ≥ 1).
std::vector<float> gaussian_blur(const std::vector<float>& img, int width, int height, int size);

// δ = blur9(w); rgb ← blur3(rgb · δ); returns the rgb result (w = δ).
GlintBuffer postprocess_glints(const GlintBuffer& in, int occlusion_size = 9, int glint_size = 3);

}  // namespace glintlab::wang2020
