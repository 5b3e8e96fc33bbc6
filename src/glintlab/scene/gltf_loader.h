// glTF 2.0 meshes (.gltf with embedded or external buffers, and .glb),
// through tinygltf.
#pragma once

#include <filesystem>
#include <string>

#include "glintlab/scene/mesh.h"

namespace glintlab {

// Loads every triangle primitive of every mesh instanced by the nodes of the
// default scene (scene 0 when none is marked; all root nodes when the file
// has no scenes), with the node hierarchy's transforms (matrix or TRS)
// applied, merged into one mesh. TEXCOORD_0 becomes the uvs unchanged (glTF
// puts the uv origin at the image's top-left corner). Normals (uvs) are kept
// only if every primitive has them. Index types u8/u16/u32 and non-indexed
// primitives are supported; textures and materials are ignored.
// The format (JSON or binary) is chosen from the file's first bytes.
// The node hierarchy is walked with an explicit stack (any depth).
// KHR_draco_mesh_compression primitives are decoded with libdraco.
// Throws glintlab::Error naming the file: missing file, parse error (with
// tinygltf's message), a cycle in the node graph (naming a node of it), an
// unsupported required extension (naming it), a malformed Draco primitive,
// unsupported primitive mode or accessor layout, out-of-range indices,
// non-finite values, no triangles.
TriangleMesh load_gltf(const std::filesystem::path& path);

// The same from the file's bytes already in memory: `name` names it in
// messages, external buffer URIs are resolved against `base_dir`. The
// fuzzing entry (src/glintlab/fuzz) reads glTF files through it.
TriangleMesh load_gltf_bytes(const std::string& bytes, const std::string& name,
                             const std::filesystem::path& base_dir);

}  // namespace glintlab
