// Pinhole perspective and orthographic cameras generating ray differentials
// (pbrt-v4 CameraBase::GenerateRayDifferential: the auxiliary rays go through
// the neighbouring pixel positions, one pixel step in x and in y).
#pragma once

#include <glm/glm.hpp>

namespace glintlab {

struct Ray {
    glm::vec3 o;
    glm::vec3 d;  // unit length
};

struct RayDifferential {
    Ray ray;
    Ray rx;  // offset by one pixel in +x
    Ray ry;  // offset by one pixel in +y (downwards on the image)
    bool has_differentials = true;
};

struct Camera {
    enum class Type { Perspective, Orthographic };
    Type type = Type::Perspective;
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_deg = 40.0f;      // vertical field of view (perspective)
    float ortho_height = 2.0f;  // world-space height of the view (orthographic)
    int width = 512;
    int height = 512;

    // film = continuous pixel coordinates, (0,0) top-left corner of the image,
    // (width, height) the bottom-right corner.
    RayDifferential generate(glm::vec2 film) const;
};

}  // namespace glintlab
