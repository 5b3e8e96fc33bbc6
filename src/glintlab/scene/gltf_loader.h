// glTF 2.0 meshes and materials (.gltf with embedded or external buffers
// and images, and .glb), through tinygltf.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "glintlab/scene/gltf_materials.h"
#include "glintlab/scene/mesh.h"
#include "glintlab/scene/texture_reader.h"

namespace glintlab {

// The triangles of the default scene of a glTF file, one part per material
// the primitives use, with the file's materials (docs/SCENE_FORMAT.md, "glTF
// materials"). The default scene is scene 0 when none is marked, all root
// nodes when the file has no scenes; the node hierarchy's transforms (matrix
// or TRS) are applied, and walked with an explicit stack (any depth). A
// part's uvs come from the TEXCOORD set its material's textures read (glTF
// puts the uv origin at the image's top-left corner). Normals (uvs) are kept
// only if every primitive of a part has them. Index types u8/u16/u32 and
// non-indexed primitives are supported. KHR_draco_mesh_compression
// primitives are decoded with libdraco. The format (JSON or binary) is
// chosen from the file's first bytes.
// Throws glintlab::Error naming the file: missing file, parse error (with
// tinygltf's message), a cycle in the node graph (naming a node of it), an
// unsupported required extension (naming it), a malformed Draco primitive,
// unsupported primitive mode or accessor layout, out-of-range indices,
// non-finite values, no triangles, an undecodable embedded image.
struct GltfScene {
    struct Part {
        TriangleMesh mesh;
        int material = -1;  // index into materials; -1: glTF's default material
    };
    std::vector<Part> parts;              // in the order of their material's first primitive
    std::vector<GltfMaterial> materials;  // every material of the file
    GltfMaterial default_material;
    // The embedded images the parts' materials read, decoded, under the
    // in-memory names their texture blocks give ("<f.glb image 0>").
    TextureFileCache images;
    size_t file_materials = 0;  // how many materials the file has (read or not)
};
GltfScene load_gltf_scene(const std::filesystem::path& path);
// The same from the file's bytes already in memory: `name` names it in
// messages, external buffer and image URIs are resolved against `base_dir`.
GltfScene load_gltf_scene_bytes(const std::string& bytes, const std::string& name,
                                const std::filesystem::path& base_dir);

// Every primitive merged into one mesh with TEXCOORD_0 as its uvs, the
// file's materials unread: the geometry a shape with its own "material"
// shades. The fuzzing entry (src/glintlab/fuzz) reads glTF files through
// load_gltf_bytes.
// `file_materials`, if given: how many materials the file has (which the
// shape's own material replaces).
TriangleMesh load_gltf(const std::filesystem::path& path, size_t* file_materials = nullptr);
TriangleMesh load_gltf_bytes(const std::string& bytes, const std::string& name,
                             const std::filesystem::path& base_dir,
                             size_t* file_materials = nullptr);

}  // namespace glintlab
