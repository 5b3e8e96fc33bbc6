// `glintlab export` (docs/INTEGRATION.md): one real-time glint model as
// standalone files for another engine — one flattened shader per language
// (GLSL 4.50, GLSL ES 3.00, HLSL Shader Model 5.0), generated from the same
// embedded .glsl sources as the OpenGL renderer, plus the model's resources
// as raw little-endian files and a JSON manifest describing them.
//
// Output layout of export_model(), in options.out_dir:
//     <model>.<lang>.frag.<ext>        the fragment stage (ext glsl | hlsl; lang glsl | glsles |
//     hlsl) <model>_<variant>.<lang>.frag.<ext>  program variants (deliot2023_noise_texture)
//     <model>.<pass>.<lang>.comp.<ext> per-environment compute passes (glsl, hlsl)
//     <model>.<resource>.f32           resources, raw little-endian float32
//     <model>.<lang>.manifest.json     what is there (docs/INTEGRATION.md "Manifest")
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "glintlab/glints/glint_desc.h"

namespace glintlab {

enum class ExportLanguage { Glsl, GlslEs, Hlsl };

// "glsl", "glsles", "hlsl"; parse_export_language throws glintlab::Error
// naming the allowed values.
const char* export_language_name(ExportLanguage lang);
ExportLanguage parse_export_language(std::string_view name);

struct ExportOptions {
    std::string model;  // a model name with a GPU back end
    ExportLanguage language = ExportLanguage::Glsl;
    std::filesystem::path out_dir = "export";
    // Optional environment map (lat-long EXR/HDR/PNG): kneiphof2025 also
    // writes its prefiltered maps for it.
    std::filesystem::path environment;
    // Optional scene file and glint material of it (`--scene`, `--material`):
    // the resources (wang2020's tables, kneiphof2025's prefiltered maps with
    // the material's K and black level) and the manifest's parameter values
    // and material uniforms are those of this material instead of the
    // model's defaults. An empty `material` picks the scene's first glint
    // material of `model`. The scene's environment is used when
    // `environment` is empty.
    std::filesystem::path scene;
    std::string material;
    // false: shaders and manifest only (no resource files, the manifest's
    // `resources` empty) — for checking shaders without building tables.
    bool resources = true;
    // The glslangValidator and spirv-cross executables the HLSL route runs
    // (searched on PATH when only a name).
    std::string glslang_validator = "glslangValidator";
    std::string spirv_cross = "spirv-cross";
};

struct ExportedFile {
    std::string name;  // relative to out_dir
    std::string kind;  // "fragment_shader", "compute_shader", "texture", "manifest"
    uint64_t bytes = 0;
};

// Writes the files of one model and language; returns them (manifest last).
// Throws glintlab::Error for an unknown model, a model without GPU back end,
// a language the model cannot be exported to, a missing tool, an
// unwritable directory, or a scene material that is missing, not a glint
// material or of another model (the message names the scene file and the
// material).
std::vector<ExportedFile> export_model(const ExportOptions& options);

// The flattened fragment stage of `model` in GLSL 4.50 or GLSL ES 3.00
// (program_options: the GPU option mask selecting a glue variant), header
// comment included. HLSL is made from the GLSL 4.50 text.
std::string export_fragment_glsl(GlintModelId model, unsigned program_options,
                                 ExportLanguage language);

// The names of the models export_model accepts, in registry order.
std::vector<std::string> exportable_models();

}  // namespace glintlab
