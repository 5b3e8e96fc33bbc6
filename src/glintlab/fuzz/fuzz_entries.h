// Fuzzing entry points (docs/VALIDATION.md, "Fuzzing"): one function per
// libFuzzer target of fuzz/ (scene JSON, glTF, OBJ, images). The libFuzzer
// mains (fuzz/*_fuzzer.cpp, built with -DGLINTLAB_FUZZ=ON and clang) and the
// regression test (fuzz_regression_test.cpp, in the ordinary suite, no clang
// needed) call the same functions, so an input that once crashed is replayed
// exactly as the fuzzer ran it.
//
// The contract checked: every input either loads, and then the result's
// invariants hold (meshes pass TriangleMesh::validate, images are finite and
// sized as they claim), or is rejected with glintlab::Error. Any other
// exception escapes (a defect: bad input must give glintlab::Error), and so
// does InvariantViolation; crashes, leaks, undefined behaviour and hangs are
// the sanitizers' and libFuzzer's to report.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace glintlab::fuzz {

enum class Target { Scene, Gltf, Obj, Image };
inline constexpr Target kTargets[] = {Target::Scene, Target::Gltf, Target::Obj, Target::Image};

// "scene", "gltf", "obj", "image": the names of the fuzzers
// (glintlab_fuzz_<name>) and of their folders under fuzz/.
std::string_view target_name(Target target);
std::optional<Target> target_from_name(std::string_view name);

// A loaded result that breaks its documented invariants.
class InvariantViolation : public std::logic_error {
  public:
    using std::logic_error::logic_error;
};

enum class Outcome { Accepted, Rejected };

// The memory limit (core/memory_limit.h) the entries set while they run:
// loads whose estimate exceeds it are rejected with glintlab::Error, as a
// user's --memory-limit would, instead of exhausting the fuzzer's 2 GiB.
inline constexpr uint64_t kMemoryLimit = uint64_t(512) << 20;

// Runs one input through the loader of `target`:
// - Scene: the bytes are a scene file (parse_json, then parse_scene) placed
//   in scratch_dir(), so relative "file" references find its assets;
// - Gltf: load_gltf_bytes (JSON or binary chosen by the magic, as for files);
// - Obj: load_obj_text;
// - Image: read_image of the bytes written to a file whose extension follows
//   the magic: "v/1\x01" .exr, "#?" .hdr, anything else .png (stb_image,
//   which itself sniffs PNG, JPEG, BMP, TGA, ...).
// `error`, if given, receives the rejection's message.
Outcome run(Target target, const uint8_t* data, size_t size, std::string* error = nullptr);

// A per-process scratch directory (created on first use, removed at exit)
// holding the assets scene inputs may reference: mesh.obj, mesh.gltf,
// mesh.glb, draco.glb, env.exr, env.hdr, height.png.
const std::filesystem::path& scratch_dir();

// Writes the seed corpus of `target` into `dir` (created): for Scene every
// scenes/*.json under `source_dir` (absolute environment paths replaced by
// env.exr of the scratch directory) and scenes using each asset; for the
// others the assets of that format. Returns the number of files written.
size_t write_seeds(Target target, const std::filesystem::path& dir,
                   const std::filesystem::path& source_dir);

}  // namespace glintlab::fuzz
