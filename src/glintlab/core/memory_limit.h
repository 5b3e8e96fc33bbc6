// Memory budget of a run (ARCHITECTURE.md "Resource limits"): before a render
// allocates its film, acceleration structure and per-pixel buffers, the
// estimate of each is summed and compared with the limit; above it the run
// fails with an error naming the biggest items and the estimate instead of
// exhausting the machine.
//
// The limit: set_memory_limit() (the CLI's --memory-limit), else the
// environment variable GLINTLAB_MEMORY_LIMIT, else 8 GiB or 3/4 of the
// physical memory, whichever is smaller. Sizes are written as a number of
// bytes with an optional suffix K, M, G, T (powers of 1024), e.g. "512M".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glintlab {

// Parses "123", "512K", "1.5G" (powers of 1024); nullopt if malformed or
// not in [1, 2^60].
std::optional<uint64_t> parse_memory_size(std::string_view text);
std::string format_memory_size(uint64_t bytes);  // "1.50 GiB"

uint64_t default_memory_limit();  // min(8 GiB, 3/4 physical memory)
// The limit in force; throws glintlab::Error naming GLINTLAB_MEMORY_LIMIT if
// that variable is set but malformed.
uint64_t memory_limit();
void set_memory_limit(std::optional<uint64_t> bytes);  // nullopt: back to env/default

struct MemoryItem {
    std::string what;  // e.g. "film 16384x16384 (RGB float, 4 buffers)"
    uint64_t bytes = 0;
};

// Throws glintlab::Error when the items sum to more than memory_limit():
// "<context> needs about X (film ...: A, ...), more than the memory limit Y
// (set by ...)". Items are listed largest first.
void require_memory(const std::vector<MemoryItem>& items, const std::string& context);

}  // namespace glintlab
