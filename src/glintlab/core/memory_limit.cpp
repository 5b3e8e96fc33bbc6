#include "glintlab/core/memory_limit.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <mutex>

#include <fmt/format.h>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

std::mutex g_mutex;
std::optional<uint64_t> g_limit;

constexpr uint64_t kGiB = uint64_t{1} << 30;

}  // namespace

std::optional<uint64_t> parse_memory_size(std::string_view text) {
    if (text.empty() || text.size() > 32) return std::nullopt;
    std::string s(text);
    double scale = 1.0;
    const char last = s.back();
    switch (last) {
        case 'K':
        case 'k':
            scale = 1024.0;
            break;
        case 'M':
        case 'm':
            scale = 1024.0 * 1024.0;
            break;
        case 'G':
        case 'g':
            scale = double(kGiB);
            break;
        case 'T':
        case 't':
            scale = double(kGiB) * 1024.0;
            break;
        default:
            break;
    }
    if (scale != 1.0) s.pop_back();
    if (s.empty() || !(std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '.'))
        return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
    const double bytes = v * scale;
    if (!(bytes >= 1.0 && bytes <= std::ldexp(1.0, 60))) return std::nullopt;
    return static_cast<uint64_t>(bytes);
}

std::string format_memory_size(uint64_t bytes) {
    const double b = double(bytes);
    if (b >= double(kGiB)) return fmt::format("{:.2f} GiB", b / double(kGiB));
    if (b >= 1024.0 * 1024.0) return fmt::format("{:.1f} MiB", b / (1024.0 * 1024.0));
    if (b >= 1024.0) return fmt::format("{:.1f} KiB", b / 1024.0);
    return fmt::format("{} B", bytes);
}

uint64_t default_memory_limit() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    uint64_t limit = 8 * kGiB;
    if (pages > 0 && page > 0) limit = std::min(limit, uint64_t(pages) / 4 * 3 * uint64_t(page));
    return limit;
}

uint64_t memory_limit() {
    {
        const std::lock_guard lock(g_mutex);
        if (g_limit) return *g_limit;
    }
    if (const char* env = std::getenv("GLINTLAB_MEMORY_LIMIT"); env && *env) {
        const std::optional<uint64_t> v = parse_memory_size(env);
        if (!v)
            fail(
                "GLINTLAB_MEMORY_LIMIT: expected a size in bytes with an optional suffix K, M, "
                "G or T (e.g. 512M, 16G), at least 1 byte, got \"{}\"",
                env);
        return *v;
    }
    return default_memory_limit();
}

void set_memory_limit(std::optional<uint64_t> bytes) {
    const std::lock_guard lock(g_mutex);
    g_limit = bytes;
}

void require_memory(const std::vector<MemoryItem>& items, const std::string& context) {
    uint64_t total = 0;
    for (const MemoryItem& i : items) total += i.bytes;
    const uint64_t limit = memory_limit();
    if (total <= limit) return;
    std::vector<MemoryItem> sorted = items;
    std::sort(sorted.begin(), sorted.end(),
              [](const MemoryItem& a, const MemoryItem& b) { return a.bytes > b.bytes; });
    std::string list;
    for (const MemoryItem& i : sorted) {
        if (i.bytes == 0) continue;
        if (!list.empty()) list += ", ";
        list += fmt::format("{}: {}", i.what, format_memory_size(i.bytes));
    }
    bool from_flag;
    {
        const std::lock_guard lock(g_mutex);
        from_flag = g_limit.has_value();
    }
    const char* env = std::getenv("GLINTLAB_MEMORY_LIMIT");
    fail(
        "{} needs about {} ({}), more than the memory limit of {} ({}); reduce the largest item "
        "or raise the limit",
        context, format_memory_size(total), list, format_memory_size(limit),
        from_flag       ? "set by --memory-limit"
        : (env && *env) ? "set by GLINTLAB_MEMORY_LIMIT"
                        : "the default: 8 GiB or 3/4 of the physical memory, whichever is "
                          "smaller; --memory-limit or GLINTLAB_MEMORY_LIMIT change it");
}

}  // namespace glintlab
