// The viewer's orbit camera (GL-free, unit-tested): left drag orbits about
// camera.target (about camera.up, then about the camera's right axis, never
// closer than ~5.7 deg to the poles of `up`), right drag pans eye and target
// together in the view plane, the wheel dollies by 0.9^steps.
#pragma once

#include <glm/glm.hpp>

#include "glintlab/scene/camera.h"

namespace glintlab {

// drag_* in pixels (x right, y down); scroll in wheel steps (positive: closer).
void orbit_camera(Camera& camera, glm::vec2 drag_left, glm::vec2 drag_right, double scroll);

}  // namespace glintlab
