// Heightfield: a plane displaced along its normal, e.g. the "glinty plane
// displaced with a high-frequency heightmap" scene.
#pragma once

#include <cstdint>
#include <functional>

#include <glm/glm.hpp>

#include "glintlab/scene/mesh.h"

namespace glintlab {

struct HeightfieldSettings {
    glm::vec2 size{2, 2};     // extent along x and z, like make_quad
    int resolution = 256;     // cells per side, in [1, 4096]
    float amplitude = 0.05f;  // displacement along +y = amplitude * height(uv)
    float frequency = 8.0f;   // procedural noise: lattice cells per unit of uv
    int octaves = 4;          // procedural noise: octaves, in [1, 16]
    uint32_t seed = 1;        // procedural noise: lattice hash seed
    glm::vec2 uv_scale{1, 1};
};

// The plane is laid out as make_quad(size, uv_scale): centred at the origin,
// u along +x, v along -z. The height callback receives the unscaled plane
// coordinate uv in [0, 1]^2 and returns a height in roughly [-1, 1] (e.g. an
// image lookup); the vertex is lifted by amplitude * height(uv) along +y.
// Without a callback, procedural_height(settings) is used.
// Normals come from central differences of the height function at the grid
// spacing (one-sided on the border), so they match the tessellated surface;
// uvs are those of the undisplaced plane, times uv_scale.
TriangleMesh make_heightfield(const HeightfieldSettings& settings,
                              std::function<float(glm::vec2 uv)> height = {});

// The built-in height function: a sum of `octaves` octaves of value noise
// (lattice values hashed from the seed, quintic interpolation so the surface
// is C2), octave k at frequency * 2^k with weight 2^-k, normalised so the
// result lies in [-1, 1]. Deterministic for a given seed.
float procedural_height(const HeightfieldSettings& settings, glm::vec2 uv);

}  // namespace glintlab
