// The curved-surface test scene shared by the CPU and GPU tests of
// "curvature" (docs/MODELS.md, "Curved surfaces"): a sphere about 20 pixels
// across at 96 × 72, so its normal turns ~0.16 rad per pixel, against a GGX
// glint lobe of α 0.05 at ln N 16, under a directional and a point light,
// 1 sample per pixel.
#pragma once

#include <nlohmann/json.hpp>

namespace glintlab::testing {

inline nlohmann::json small_curved_sphere(const char* model, const char* curvature) {
    return {{"camera", {{"eye", {0.0, 1.27, 2.72}}, {"target", {0, 0.15, 0}}, {"fov_deg", 20}}},
            {"film", {{"width", 96}, {"height", 72}}},
            {"render", {{"integrator", "direct"}, {"spp", 1}, {"seed", 1}}},
            {"materials",
             {{{"name", "m"},
               {"type", "glint"},
               {"model", model},
               {"ndf", "ggx"},
               {"roughness", 0.05},
               {"log_density", 16},
               {"curvature", curvature}}}},
            {"shapes",
             {{{"type", "sphere"}, {"center", {0, 0.15, 0}}, {"radius", 0.15}, {"material", "m"}}}},
            {"lights",
             {{{"type", "directional"}, {"direction", {0.3, 0.8, 0.6}}, {"irradiance", 2.0}},
              {{"type", "point"}, {"position", {1.0, 1.5, 0.5}}, {"intensity", 1.0}}}}};
}

}  // namespace glintlab::testing
