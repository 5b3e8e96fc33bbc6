// The bright sources of a lat-long environment map (a sun, a studio's lamps,
// a window) taken out of it, for real-time shading by filtered importance
// sampling (realtime/shaders/forward.frag.glsl). A few dozen prefiltered
// samples of a reflection lobe are a kernel estimate: each reads the map
// averaged over its share of the sphere, which in a narrow lobe's tail is
// steradians wide, so a source there is weighted as if it sat where the lobe
// is much stronger (blender's studio map on a GGX 0.05 plane at grazing view:
// 2.3x the CPU's image) and a point-like one is drawn as a pattern of
// petals. The sources are therefore shaded as K directions inside them (a
// quadrature of each) and the samples read the map without them.
// Contrast criterion as kneiphof2025's sun (glints/kneiphof2025/kneiphof2025_prefilter.h).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "glintlab/core/image.h"

namespace glintlab {

struct EnvironmentSourceSplit {
    // The map with each source's texels brought down to the mean of their
    // surroundings (colour per channel, never above the texel): the
    // residual the lobe samples read, without a plateau or a hole where a
    // source was (either would be smeared over a blurred lookup's footprint,
    // the plateau too bright, the hole too dark).
    Image residual;
    // K sample directions in the map's own frame (EnvironmentMap::uv_to_direction
    // at rotation 0; a renderer turns them by the environment's rotation) and
    // the RGB power each carries (radiance × solid angle, W/m² at normal
    // incidence per unit scale); residual + powers keep the map's power.
    // Empty: no source.
    std::vector<glm::vec3> directions;
    std::vector<glm::vec3> powers;
    // Per direction, the angular radius (radians) of a disc of the solid
    // angle it stands for (its source's texels' over its number of
    // directions): a renderer widens a narrow lobe by it, so that a lamp
    // reflected in a near-mirror is a patch, not a pattern of dots.
    std::vector<float> radii;
};

// A map has sources when its brightest texel's luminance exceeds kContrast ×
// the map's solid-angle mean. Its sources are the connected sets
// (8-neighbours, wrapping in u) of texels whose luminance is at least
// max(kFraction × the brightest, kContrast × mean); their power is what they
// have above their surroundings. Kept are the brightest source and every
// other worth half a sample (power ≥ 1/(2K) of all sources'), at most K;
// the others stay in the residual. Each kept source gets one sample, the
// rest of the K by largest remainder of K × its share; its n samples are
// Hammersley points ((k + 1/2)/n, radical inverse of k) through its
// power's distribution over rows, then texels along the row, each carrying
// 1/n of its power in its texel's colour.
// With texel_contrast > 0 a source's texels are instead those at least
// texel_contrast × the mean (the map still needs a texel above kContrast ×
// mean to have sources): a lower bar takes a lamp's halo with it, which a
// renderer that reads the residual through coarse blurred levels (kneiphof2025's
// prefilter) would otherwise smear as well.
struct EnvironmentSourceCriteria {
    static constexpr float kContrast = 50.0f;
    static constexpr float kFraction = 0.05f;
};
EnvironmentSourceSplit split_environment_sources(const Image& map, int samples,
                                                 float texel_contrast = 0.0f);

}  // namespace glintlab
