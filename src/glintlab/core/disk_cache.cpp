#include "glintlab/core/disk_cache.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <fmt/format.h>

namespace glintlab {
namespace {

constexpr char kMagic[8] = {'G', 'L', 'C', 'A', 'C', 'H', 'E', '1'};

struct Header {
    char magic[8];
    uint64_t key;
    uint64_t payload_size;
    uint64_t checksum;
};

std::atomic<bool> g_disabled{false};
std::atomic<uint64_t> g_temp_counter{0};

void warn(const std::string& message) {
    fmt::print(stderr, "glintlab: warning: {}\n", message);
}

}  // namespace

uint64_t fnv1a64(const void* data, size_t size, uint64_t h) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

CacheKey::CacheKey(std::string_view table_name, uint32_t table_version) : h_(fnv1a64("", 0)) {
    add(std::string_view(GLINTLAB_VERSION));
    add(table_name);
    add(table_version);
}

CacheKey& CacheKey::add(std::string_view s) {
    add(uint64_t(s.size()));
    h_ = fnv1a64(s.data(), s.size(), h_);
    return *this;
}

CacheKey& CacheKey::add_bytes(const void* data, size_t size) {
    h_ = fnv1a64(data, size, h_);
    return *this;
}

CacheKey& CacheKey::add_file(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::vector<char> buf(1 << 16);
    uint64_t size = 0, h = fnv1a64("", 0);
    while (in) {
        in.read(buf.data(), std::streamsize(buf.size()));
        const auto n = size_t(in.gcount());
        h = fnv1a64(buf.data(), n, h);
        size += n;
    }
    add(size);
    return add(h);
}

std::filesystem::path disk_cache_dir() {
    if (const char* d = std::getenv("GLINTLAB_CACHE_DIR"); d && *d) return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
        return std::filesystem::path(x) / "glintlab";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "glintlab";
    return {};
}

bool disk_cache_enabled() {
    if (g_disabled.load()) return false;
    const char* off = std::getenv("GLINTLAB_NO_CACHE");
    if (off && *off && std::string_view(off) != "0") return false;
    return !disk_cache_dir().empty();
}

void set_disk_cache_enabled(bool enabled) {
    g_disabled.store(!enabled);
}

std::filesystem::path disk_cache_file(std::string_view name, uint64_t key) {
    return disk_cache_dir() / fmt::format("{}-{:016x}.bin", name, key);
}

std::optional<std::vector<unsigned char>> disk_cache_load(std::string_view name, uint64_t key) {
    if (!disk_cache_enabled()) return std::nullopt;
    const std::filesystem::path file = disk_cache_file(name, key);
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status)) return std::nullopt;
    // Opening a FIFO or a device blocks (or reads forever): only a regular
    // file is read; anything else is a miss, and the store that follows
    // replaces the entry (rename) or warns when it cannot.
    if (!std::filesystem::is_regular_file(status)) {
        warn(
            fmt::format("table cache entry {} is not a regular file; it is ignored and the table "
                        "rebuilt",
                        file.string()));
        return std::nullopt;
    }
    std::ifstream in(file, std::ios::binary);
    Header h{};
    std::vector<unsigned char> payload;
    bool ok = bool(in.read(reinterpret_cast<char*>(&h), sizeof h)) &&
              std::memcmp(h.magic, kMagic, sizeof kMagic) == 0 && h.key == key;
    if (ok) {
        const auto size = std::filesystem::file_size(file, ec);
        ok = !ec && size == sizeof h + h.payload_size;
    }
    if (ok) {
        payload.resize(size_t(h.payload_size));
        ok = bool(in.read(reinterpret_cast<char*>(payload.data()),
                          std::streamsize(payload.size()))) &&
             fnv1a64(payload.data(), payload.size()) == h.checksum;
    }
    if (ok) return payload;
    warn(
        fmt::format("table cache file {} is corrupt or truncated (header, size or checksum "
                    "mismatch); it is removed and the table rebuilt",
                    file.string()));
    in.close();
    std::filesystem::remove(file, ec);
    return std::nullopt;
}

void disk_cache_reject(std::string_view name, uint64_t key, std::string_view why) {
    const std::filesystem::path file = disk_cache_file(name, key);
    warn(fmt::format("table cache file {} is rejected ({}); it is removed and the table rebuilt",
                     file.string(), why));
    std::error_code ec;
    std::filesystem::remove(file, ec);
}

bool disk_cache_store(std::string_view name, uint64_t key,
                      const std::vector<unsigned char>& payload) {
    if (!disk_cache_enabled()) return false;
    const std::filesystem::path file = disk_cache_file(name, key);
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    // A temporary name unique to this process and call: concurrent writers
    // (threads, or processes sharing the directory) never share a temp file.
    const std::filesystem::path tmp =
        file.parent_path() / fmt::format(".{}.{}.{}.{}.tmp", file.filename().string(), ::getpid(),
                                         std::hash<std::thread::id>{}(std::this_thread::get_id()),
                                         g_temp_counter++);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        Header h{};
        std::memcpy(h.magic, kMagic, sizeof kMagic);
        h.key = key;
        h.payload_size = payload.size();
        h.checksum = fnv1a64(payload.data(), payload.size());
        out.write(reinterpret_cast<const char*>(&h), sizeof h);
        out.write(reinterpret_cast<const char*>(payload.data()), std::streamsize(payload.size()));
        out.close();
        if (!out) {
            warn(fmt::format("cannot write the table cache file {}: the table is not cached",
                             tmp.string()));
            std::filesystem::remove(tmp, ec);
            return false;
        }
    }
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        warn(fmt::format("cannot rename {} to {}: {}", tmp.string(), file.string(), ec.message()));
        std::filesystem::remove(tmp, ec);
        return false;
    }
    return true;
}

}  // namespace glintlab
