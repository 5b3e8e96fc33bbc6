// A compact sun taken out of a lat-long environment map, for real-time
// shading by filtered importance sampling (realtime/shaders/forward.frag.glsl).
// A few dozen prefiltered samples of a reflection lobe are a kernel estimate
// that puts too much or too little of a point-like source in and draws it as
// a pattern of petals; the sun is therefore shaded as K directions inside it
// (a quadrature of its disc) and the samples read the map without it.
// Sun criterion as kneiphof2025's (glints/kneiphof2025/kneiphof2025_prefilter.h).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "glintlab/core/image.h"

namespace glintlab {

struct EnvironmentSunSplit {
    // The map with the sun's texels brought down to the threshold luminance
    // (their colour kept): the residual the lobe samples read, continuous
    // with the sun's surroundings (a hole of zeros darkened every blurred
    // lookup near it).
    Image residual;
    // K sample directions in the map's own frame (EnvironmentMap::uv_to_direction
    // at rotation 0; a renderer turns them by the environment's rotation) and
    // the RGB power each carries (radiance × solid angle, W/m² at normal
    // incidence per unit scale); the powers sum to the sun's. Empty: no sun.
    std::vector<glm::vec3> directions;
    std::vector<glm::vec3> powers;
};

// The brightest texel is a sun when its luminance exceeds kContrast × the
// map's solid-angle mean; the sun is every texel within kConeDeg of it whose
// luminance is at least max(kFraction × its luminance, kContrast × mean).
// The sun's power is what its texels have above the threshold; the K samples
// are the quantiles (k + 1/2) / K of that luminance power over its texels
// (row-major), placed inside their texel along u by the quantile's
// fraction, each carrying 1/K of it in its texel's colour.
struct EnvironmentSunCriteria {
    static constexpr float kContrast = 50.0f;
    static constexpr float kFraction = 0.05f;
    static constexpr float kConeDeg = 4.0f;
};
EnvironmentSunSplit split_environment_sun(const Image& map, int samples);

}  // namespace glintlab
