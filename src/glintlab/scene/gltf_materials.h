// glTF 2.0 materials as scene-format materials (docs/SCENE_FORMAT.md, "glTF
// materials"): pbrMetallicRoughness becomes a "metallic_roughness" material
// whose inputs are the file's factors and textures in the texture form, so
// the scene loader reads, checks and filters them as it does a scene's own.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace glintlab {

struct GltfMaterial {
    std::string name;      // the file's name, or "material N"; "default" for glTF's default
    nlohmann::json block;  // a scene-format material without "name"
    int uv_set = 0;        // the TEXCOORD_n its textures read
    bool metallic = true;  // metallicFactor >= 0.5: which side a glint override takes
    // What the material has that glintlab does not read, one phrase each
    // (the loader's warning names them).
    std::vector<std::string> unread;
    std::vector<int> images;  // the file's images its textures read
};

// Material `index` of the glTF document `gltf` (index -1: glTF's default
// material, white, metallic 1, roughness 1). `image_names[i]` is how a
// texture block names image i: a file path, or an in-memory name
// ("<f.glb image 0>") the caller decodes. `file` names the file in
// messages. Throws glintlab::Error naming the file and the material for
// indices out of range and textures reading two uv sets.
GltfMaterial translate_gltf_material(const nlohmann::json& gltf, int index,
                                     const std::vector<std::string>& image_names,
                                     const std::string& file);

// The material a shape's "material_overrides" entry describes: `override`
// with the file material's inputs for the keys it does not set (a glint
// material keeps the file's roughness map, normal map, and base colour as
// its "color" on the metallic side or as a "base_albedo" under a dielectric
// coat on the other). Without "type" the override changes keys of the
// file's metallic_roughness material. Phrases for what the override's type
// cannot carry over go to `notes`.
nlohmann::json apply_material_override(const GltfMaterial& file_material,
                                       const nlohmann::json& override_block,
                                       std::vector<std::string>* notes);

}  // namespace glintlab
