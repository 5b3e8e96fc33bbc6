// The scene shared by the CPU and GPU tests of normal maps that face away
// from the viewer (core/slope_frame.glsl visible_slope): a quad facing +z
// whose constant map tilts the normal 70° towards +y, seen from −y at 26°
// above it, under a constant white environment.
#pragma once

#include <filesystem>
#include <fstream>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "glintlab/core/image.h"

namespace glintlab::testing {

// Writes the scene's away.exr (the map), white.exr (the environment) and
// quad.obj (uvs with v down the image, as glTF) into `dir`.
inline void write_facing_away_assets(const std::filesystem::path& dir) {
    write_exr(Image(4, 4, glm::normalize(glm::vec3(0.0f, 2.75f, 1.0f))), dir / "away.exr");
    write_exr(Image(16, 8, glm::vec3(1.0f)), dir / "white.exr");
    std::ofstream obj(dir / "quad.obj");
    obj << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 1\nvt 1 1\nvt 1 0\nvt 0 0\n"
           "vn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";
}

// The scene document with `material` (named and given the map here) on a
// size × size film.
inline nlohmann::json facing_away_scene(nlohmann::json material, int size) {
    material["name"] = "m";
    material["normal_map"] = {{"texture", "away.exr"}, {"encoding", "signed"}};
    return {{"camera", {{"eye", {0.0, -2.6, 1.3}}, {"target", {0, 0, 0}}, {"fov_deg", 25}}},
            {"film", {{"width", size}, {"height", size}}},
            {"render", {{"integrator", "direct"}, {"spp", 4}, {"seed", 1}}},
            {"materials", {material}},
            {"shapes", {{{"type", "obj"}, {"file", "quad.obj"}, {"material", "m"}}}},
            {"lights", {{{"type", "environment"}, {"file", "white.exr"}}}}};
}

}  // namespace glintlab::testing
