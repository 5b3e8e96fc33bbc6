#include "glintlab/core/memory_limit.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

TEST(MemoryLimit, ParsesSizesWithBinarySuffixes) {
    EXPECT_EQ(parse_memory_size("123"), 123u);
    EXPECT_EQ(parse_memory_size("2K"), 2048u);
    EXPECT_EQ(parse_memory_size("512M"), 512u << 20);
    EXPECT_EQ(parse_memory_size("1.5G"), (3ull << 30) / 2);
    EXPECT_EQ(parse_memory_size("2T"), 2ull << 40);
    for (const char* bad : {"", "G", "-1G", "0", "1X", "nan", "inf", "1e300", "1.2.3M", " 5"})
        EXPECT_FALSE(parse_memory_size(bad).has_value()) << bad;
}

// Under a tiny limit the error lists the items largest first with the total
// and says where the limit came from; within it nothing is thrown.
TEST(MemoryLimit, TooBigNamesTheItemsAndTheLimit) {
    set_memory_limit(uint64_t{1} << 20);
    const std::vector<MemoryItem> items = {{"small", 1000}, {"film 9x9", 3u << 20}};
    try {
        require_memory(items, "render of a.json");
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("render of a.json needs about 3.0 MiB"), std::string::npos) << m;
        EXPECT_LT(m.find("film 9x9: 3.0 MiB"), m.find("small: 1000 B")) << m;
        EXPECT_NE(m.find("1.0 MiB"), std::string::npos) << m;
        EXPECT_NE(m.find("--memory-limit"), std::string::npos) << m;
    }
    EXPECT_NO_THROW(require_memory({{"small", 1000}}, "x"));
    set_memory_limit(std::nullopt);
}

TEST(MemoryLimit, EnvironmentVariableAndDefault) {
    set_memory_limit(std::nullopt);
    ::setenv("GLINTLAB_MEMORY_LIMIT", "64M", 1);
    EXPECT_EQ(memory_limit(), 64u << 20);
    ::setenv("GLINTLAB_MEMORY_LIMIT", "lots", 1);
    EXPECT_THROW(memory_limit(), Error);
    ::unsetenv("GLINTLAB_MEMORY_LIMIT");
    EXPECT_EQ(memory_limit(), default_memory_limit());
    EXPECT_LE(default_memory_limit(), 8ull << 30);
    EXPECT_GT(default_memory_limit(), 0u);
}

}  // namespace
}  // namespace glintlab
