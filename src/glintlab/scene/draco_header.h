// The sizes a Draco-encoded mesh declares, read before Draco decodes it.
//
// Draco's decoders allocate their connectivity tables at the face and
// vertex counts the stream declares (draco::CornerTable::Reset from the
// Edgebreaker header), before reading the data that would show the counts
// to be false: a glTF of 856 bytes declaring 2.4 × 10⁸ faces made Draco
// allocate 2.9 GB (found by the glTF fuzzer; fuzz/regressions/gltf/
// draco_edgebreaker_faces_2e8.glb). The counts cannot be bounded by the
// stream's size, since Draco's entropy coding legitimately packs a regular
// mesh into a few bits per face, so they are checked against the memory
// limit (core/memory_limit.h) instead.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace glintlab {

struct DracoMeshSizes {
    uint64_t faces = 0;
    uint64_t vertices = 0;  // Edgebreaker: encoded vertices; sequential: points
    bool edgebreaker = false;
};

// Reads the header of a Draco mesh stream (Draco bitstream 1.x–2.2: magic,
// version, encoder type and method, flags, metadata if flagged, then the
// connectivity header of the sequential or Edgebreaker method) as Draco
// 1.5 reads it. nullopt where Draco itself will refuse the stream before
// allocating (not "DRACO", not a mesh, unknown method, truncated header).
std::optional<DracoMeshSizes> read_draco_mesh_sizes(const char* data, size_t size);

// Throws glintlab::Error ("<where>: decoding the Draco mesh needs about ...")
// when the declared sizes need more than the memory limit.
void require_draco_memory(const DracoMeshSizes& sizes, const std::string& where);

}  // namespace glintlab
