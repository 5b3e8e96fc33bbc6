// On-disk cache of precomputed tables (ARCHITECTURE.md "Table cache").
//
// A table is stored under a 64-bit key hashing every input it depends on (its
// parameters, the content of any input file, a per-table version constant
// and the glintlab version), in
//   $GLINTLAB_CACHE_DIR, else $XDG_CACHE_HOME/glintlab, else ~/.cache/glintlab
// as <name>-<key in hex>.bin: a header (magic, key, payload size, FNV-1a
// checksum of the payload) and the payload. Writes go to a temporary file in
// the same directory, then rename() (atomic: a reader sees the old file, the
// new one or none). A file whose header, size or checksum does not match is
// never trusted: a warning is printed, the file is removed and the table
// rebuilt. GLINTLAB_NO_CACHE=1 (or set_disk_cache_enabled(false), the CLI's
// --no-cache) turns the cache off; failures to write only warn.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glintlab {

// FNV-1a 64 of bytes, continuing from `h`.
uint64_t fnv1a64(const void* data, size_t size, uint64_t h = 14695981039346656037ull);

// Accumulates a cache key from the inputs of a table.
class CacheKey {
  public:
    explicit CacheKey(std::string_view table_name, uint32_t table_version);
    CacheKey& add(std::string_view s);
    CacheKey& add_bytes(const void* data, size_t size);
    template <typename T>
    CacheKey& add(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        return add_bytes(&v, sizeof v);
    }
    // The file's size and a hash of its content (not its path or time).
    CacheKey& add_file(const std::filesystem::path& file);
    uint64_t value() const { return h_; }

  private:
    uint64_t h_;
};

std::filesystem::path disk_cache_dir();
bool disk_cache_enabled();
void set_disk_cache_enabled(bool enabled);  // overrides GLINTLAB_NO_CACHE when false

std::filesystem::path disk_cache_file(std::string_view name, uint64_t key);

// The payload stored under (name, key), or nullopt (absent, disabled, or
// corrupt: then a warning names the file and it is removed).
std::optional<std::vector<unsigned char>> disk_cache_load(std::string_view name, uint64_t key);
// For a payload that disk_cache_load returned but that does not parse as the
// table expects (a layout version or sizes that do not match its
// parameters): warns, naming the file and `why`, and removes the file.
void disk_cache_reject(std::string_view name, uint64_t key, std::string_view why);
// Stores the payload atomically; returns false (after a warning) on failure.
bool disk_cache_store(std::string_view name, uint64_t key,
                      const std::vector<unsigned char>& payload);

// Helpers to (de)serialise arrays of trivially copyable values.
class ByteWriter {
  public:
    // resize + memcpy rather than vector::insert, whose inlined copy GCC 12
    // misreports (-Wstringop-overflow).
    template <typename T>
    void put(const T& v) {
        append(&v, sizeof v);
    }
    template <typename T>
    void put_vector(const std::vector<T>& v) {
        put(uint64_t(v.size()));
        append(v.data(), v.size() * sizeof(T));
    }
    std::vector<unsigned char> bytes;

  private:
    void append(const void* data, size_t size) {
        if (size == 0) return;
        const size_t n = bytes.size();
        bytes.resize(n + size);
        std::memcpy(bytes.data() + n, data, size);
    }
};

class ByteReader {
  public:
    explicit ByteReader(const std::vector<unsigned char>& b) : bytes_(b) {}
    template <typename T>
    bool get(T& v) {
        if (bytes_.size() - pos_ < sizeof v) return false;
        std::memcpy(&v, bytes_.data() + pos_, sizeof v);
        pos_ += sizeof v;
        return true;
    }
    template <typename T>
    bool get_vector(std::vector<T>& v) {
        uint64_t n = 0;
        if (!get(n) || n > (bytes_.size() - pos_) / sizeof(T)) return false;
        v.resize(size_t(n));
        // An empty vector's data() may be null, which memcpy must never get.
        if (n != 0) std::memcpy(v.data(), bytes_.data() + pos_, size_t(n) * sizeof(T));
        pos_ += size_t(n) * sizeof(T);
        return true;
    }
    bool at_end() const { return pos_ == bytes_.size(); }

  private:
    const std::vector<unsigned char>& bytes_;
    size_t pos_ = 0;
};

}  // namespace glintlab
