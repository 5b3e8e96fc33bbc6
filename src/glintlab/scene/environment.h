// Lat-long environment map with importance sampling.
// Convention (y up): a direction d = (sinθ sinφ, cosθ, −sinθ cosφ) maps to
// u = 0.5 + φ/2π (φ measured from −z towards +x, minus the rotation about +y),
// v = θ/π (v = 0 at the zenith, the image's top row).
#pragma once

#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "glintlab/core/distribution.h"
#include "glintlab/core/image.h"

namespace glintlab {

class EnvironmentMap {
  public:
    // image: linear Rec.709 radiance; scale multiplies it; rotation about +y.
    EnvironmentMap(Image image, float scale, float rotation_deg);
    static EnvironmentMap constant(glm::vec3 radiance);

    glm::vec3 eval(glm::vec3 dir) const;  // bilinear radiance in world direction dir
    // Samples a direction proportionally to (a conservative bound of) luminance.
    glm::vec3 sample(glm::vec2 u, glm::vec3* dir, float* pdf) const;
    float pdf(glm::vec3 dir) const;  // solid-angle density of sample()

    glm::vec2 direction_to_uv(glm::vec3 dir) const;
    glm::vec3 uv_to_direction(glm::vec2 uv) const;
    const Image& image() const { return image_; }
    float scale() const { return scale_; }
    float rotation_deg() const { return rotation_deg_; }

  private:
    Image image_;
    float scale_ = 1.0f;
    float rotation_deg_ = 0.0f;
    float rotation_rad_ = 0.0f;
    Distribution2D distribution_;
};

}  // namespace glintlab
