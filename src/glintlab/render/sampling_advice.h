// Warnings for renders whose sample count is far below what an estimator
// needs, from measured convergence rates (docs/MODELS.md, jakob2014
// "Samples under environment lights"). Advice, not errors: a low-spp preview
// is legitimate, but a black image dotted with sparkles should not surprise.
#pragma once

#include <string>
#include <vector>

#include "glintlab/scene/scene.h"

namespace glintlab {

// jakob2014 under an environment light (light sampling + MIS over the γ cone,
// 002 §4): the per-pixel relative RMSE of the image falls as
// kJakob2014EnvironmentErrorAt1Spp / sqrt(spp) (measured on blender-data maps).
inline constexpr double kJakob2014EnvironmentErrorAt1Spp = 1.8;
// Below this many samples per pixel the expected error exceeds 25 %.
inline constexpr int kJakob2014EnvironmentMinSpp = 52;

// One line per material that needs more samples than scene.render.spp.
std::vector<std::string> sampling_advice(const Scene& scene);

}  // namespace glintlab
