#include "glintlab/scene/draco_header.h"

#include <cstring>
#include <vector>

#include <fmt/format.h>

#include "glintlab/core/memory_limit.h"

namespace glintlab {
namespace {

// Bytes of the stream read in Draco's order; every read fails past the end.
class DracoReader {
  public:
    DracoReader(const char* data, size_t size) : data_(data), size_(size) {}
    size_t remaining() const { return size_ - pos_; }
    bool u8(uint32_t& out) {
        if (pos_ >= size_) return false;
        out = uint8_t(data_[pos_++]);
        return true;
    }
    bool u16(uint32_t& out) {  // little-endian, as Draco's DecoderBuffer::Decode
        uint32_t lo = 0, hi = 0;
        if (!u8(lo) || !u8(hi)) return false;
        out = lo | hi << 8;
        return true;
    }
    bool u32(uint32_t& out) {
        uint32_t lo = 0, hi = 0;
        if (!u16(lo) || !u16(hi)) return false;
        out = lo | hi << 16;
        return true;
    }
    // draco::DecodeVarint<uint32_t>: 7 bits a byte, least significant
    // first, at most 5 bytes; bits past 32 are shifted out as Draco's
    // uint32 arithmetic drops them.
    bool varint(uint32_t& out) {
        uint64_t value = 0;
        for (int i = 0; i < 5; ++i) {
            uint32_t byte = 0;
            if (!u8(byte)) return false;
            value |= uint64_t(byte & 0x7f) << (7 * i);
            if (!(byte & 0x80)) {
                out = uint32_t(value);
                return true;
            }
        }
        return false;
    }
    bool skip(uint64_t n) {
        if (n > remaining()) return false;
        pos_ += size_t(n);
        return true;
    }

  private:
    const char* data_;
    size_t size_;
    size_t pos_ = 0;
};

// draco::MetadataDecoder: an element is its entries (name: u8 length and
// bytes; value: varint length and bytes) and its sub-elements (name, then
// an element), walked with a stack as Draco walks them.
bool skip_metadata_element(DracoReader& r) {
    auto entries = [&r] {
        uint32_t count = 0;
        if (!r.varint(count)) return false;
        for (uint32_t i = 0; i < count; ++i) {
            uint32_t name = 0, value = 0;
            if (!r.u8(name) || !r.skip(name) || !r.varint(value) || !r.skip(value)) return false;
        }
        return true;
    };
    auto children = [&r](std::vector<uint32_t>& stack) {
        uint32_t count = 0;
        if (!r.varint(count) || count > r.remaining()) return false;  // Draco's own bound
        stack.push_back(count);
        return true;
    };
    std::vector<uint32_t> stack;
    if (!entries() || !children(stack)) return false;
    while (!stack.empty()) {
        if (stack.back() == 0) {
            stack.pop_back();
            continue;
        }
        --stack.back();
        uint32_t name = 0;
        if (!r.u8(name) || !r.skip(name) || !entries() || !children(stack)) return false;
    }
    return true;
}

bool skip_geometry_metadata(DracoReader& r) {
    uint32_t attributes = 0;
    if (!r.varint(attributes)) return false;
    for (uint32_t i = 0; i < attributes; ++i) {
        uint32_t unique_id = 0;
        if (!r.varint(unique_id) || !skip_metadata_element(r)) return false;
    }
    return skip_metadata_element(r);
}

}  // namespace

std::optional<DracoMeshSizes> read_draco_mesh_sizes(const char* data, size_t size) {
    if (size < 5 || std::memcmp(data, "DRACO", 5) != 0) return std::nullopt;
    DracoReader r(data + 5, size - 5);
    uint32_t major = 0, minor = 0, type = 0, method = 0, flags = 0;
    if (!r.u8(major) || !r.u8(minor) || !r.u8(type) || !r.u8(method) || !r.u16(flags))
        return std::nullopt;
    const uint32_t version = major << 8 | minor;
    if (type != 1 || method > 1) return std::nullopt;  // not a triangular mesh / unknown method
    if ((flags & 0x8000) && !skip_geometry_metadata(r)) return std::nullopt;
    // Counts are 32-bit little-endian before bitstream 2.0 (Edgebreaker) or
    // 2.2 (sequential), varints since.
    auto count = [&](uint32_t& out, uint32_t varint_since) {
        return version < varint_since ? r.u32(out) : r.varint(out);
    };
    DracoMeshSizes sizes;
    uint32_t faces = 0, vertices = 0;
    if (method == 0) {  // MeshSequentialDecoder::DecodeConnectivity
        if (!count(faces, 0x0202) || !count(vertices, 0x0202)) return std::nullopt;
    } else {  // MeshEdgebreakerDecoder: traverser type, then the connectivity header
        sizes.edgebreaker = true;
        uint32_t traverser = 0, new_vertices = 0;
        if (!r.u8(traverser)) return std::nullopt;
        if (version < 0x0202 && !count(new_vertices, 0x0200)) return std::nullopt;
        if (!count(vertices, 0x0200) || !count(faces, 0x0200)) return std::nullopt;
    }
    sizes.faces = faces;
    sizes.vertices = vertices;
    return sizes;
}

void require_draco_memory(const DracoMeshSizes& sizes, const std::string& where) {
    // Per face: Draco's corner table (corner to vertex and opposite corner,
    // 3 x 2 x 4 bytes), its mesh's faces (12) and ours (12); per vertex:
    // Draco's vertex-to-corner map and attribute values (~32 bytes with
    // position, normal and uv) and our vertex (32).
    require_memory({{fmt::format("Draco mesh of {} faces", sizes.faces), sizes.faces * 48},
                    {fmt::format("its {} vertices", sizes.vertices), sizes.vertices * 64}},
                   fmt::format("{}: decoding the Draco mesh ({} encoding)", where,
                               sizes.edgebreaker ? "Edgebreaker" : "sequential"));
}

}  // namespace glintlab
