// Wavefront OBJ meshes (through tinyobjloader).
#pragma once

#include <filesystem>
#include <string>

#include "glintlab/scene/mesh.h"

namespace glintlab {

// Loads every shape of the file into one mesh: polygons are triangulated and
// positions/normals/uvs are de-indexed into one vertex per distinct
// (position, normal, uv) index triple. Normals (uvs) are kept only if every
// face corner has one; otherwise the mesh has none (faceted shading / no uv
// parameterization). Normals are normalised. Materials are ignored.
// Throws glintlab::Error naming the file when it is missing or malformed,
// has no triangles, indices out of range or non-finite values.
TriangleMesh load_obj(const std::filesystem::path& path);

// The same from the file's text already in memory (`name` names it in
// messages; "mtllib" lines are ignored, materials are not read anyway).
// The fuzzing entry (src/glintlab/fuzz) reads OBJ files through it.
TriangleMesh load_obj_text(const std::string& text, const std::string& name);

}  // namespace glintlab
