#include "glintlab/realtime/orbit_camera.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace glintlab {

void orbit_camera(Camera& c, glm::vec2 drag_left, glm::vec2 drag_right, double scroll) {
    glm::vec3 offset = c.eye - c.target;
    const float radius = glm::length(offset);
    if (!(radius > 0.0f) || !(glm::dot(c.up, c.up) > 0.0f)) return;
    const glm::vec3 up = glm::normalize(c.up);
    // The right axis of the view; undefined when looking along `up`.
    const auto right_of = [&](glm::vec3 o) {
        const glm::vec3 r = glm::cross(-o, up);
        const float len = glm::length(r);
        return len > 1e-6f * radius ? r / len : glm::vec3(0.0f);
    };
    if (drag_left != glm::vec2(0.0f)) {
        offset = glm::angleAxis(-0.01f * drag_left.x, up) * offset;
        const glm::vec3 right = right_of(offset);
        if (right != glm::vec3(0.0f)) {
            const glm::vec3 tilted = glm::angleAxis(-0.01f * drag_left.y, right) * offset;
            if (std::abs(glm::dot(glm::normalize(tilted), up)) < 0.995f) offset = tilted;
        }
    }
    if (drag_right != glm::vec2(0.0f)) {
        const glm::vec3 right = right_of(offset);
        if (right != glm::vec3(0.0f)) {
            const glm::vec3 cam_up = glm::cross(right, -glm::normalize(offset));
            c.target += (-drag_right.x * right + drag_right.y * cam_up) * (0.0015f * radius);
        }
    }
    if (scroll != 0.0) offset *= static_cast<float>(std::pow(0.9, scroll));
    c.eye = c.target + offset;
}

}  // namespace glintlab
