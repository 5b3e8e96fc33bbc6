#include "glintlab/scene/camera.h"

#include <cmath>

namespace glintlab {
namespace {

struct CameraFrame {
    glm::vec3 right, up, forward;
};

CameraFrame frame_of(const Camera& c) {
    const glm::vec3 forward = glm::normalize(c.target - c.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    const glm::vec3 up = glm::cross(right, forward);
    return {right, up, forward};
}

Ray ray_at(const Camera& c, const CameraFrame& f, glm::vec2 film) {
    const float aspect = static_cast<float>(c.width) / static_cast<float>(c.height);
    // Normalised device coordinates in [-1, 1], y up.
    const float sx = (2.0f * film.x / static_cast<float>(c.width) - 1.0f);
    const float sy = (1.0f - 2.0f * film.y / static_cast<float>(c.height));
    if (c.type == Camera::Type::Perspective) {
        const float t = std::tan(glm::radians(c.fov_deg) * 0.5f);
        const glm::vec3 d = f.forward + f.right * (sx * t * aspect) + f.up * (sy * t);
        return {c.eye, glm::normalize(d)};
    }
    const float h = c.ortho_height * 0.5f;
    return {c.eye + f.right * (sx * h * aspect) + f.up * (sy * h), f.forward};
}

}  // namespace

RayDifferential Camera::generate(glm::vec2 film) const {
    const CameraFrame f = frame_of(*this);
    RayDifferential r;
    r.ray = ray_at(*this, f, film);
    r.rx = ray_at(*this, f, film + glm::vec2(1.0f, 0.0f));
    r.ry = ray_at(*this, f, film + glm::vec2(0.0f, 1.0f));
    return r;
}

}  // namespace glintlab
