// kneiphof2025's DFG / E_D table through the on-disk cache: a hit returns
// the computed table bit for bit and a corrupt file is recomputed.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>

#include "glintlab/core/disk_cache.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"

namespace glintlab {
namespace {

bool same_bits(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

TEST(Kneiphof2025DfgCache, HitEqualsComputedAndCorruptFileIsRecomputed) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("glintlab_kneiphof2025_dfg_cache_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    ::setenv("GLINTLAB_CACHE_DIR", dir.c_str(), 1);
    ::unsetenv("GLINTLAB_NO_CACHE");
    const std::vector<glm::vec3> computed = Kneiphof2025DfgLut::compute_table();
    ASSERT_EQ(computed.size(), size_t(Kneiphof2025DfgLut::kSize) * Kneiphof2025DfgLut::kSize);
    // An entry is the integrand at its texel centre (row = roughness).
    const glm::vec3 e = Kneiphof2025DfgLut::integrate(3.5f / 32, 5.5f / 32, 2048);
    EXPECT_EQ(std::memcmp(&computed[5 * 32 + 3], &e, sizeof e), 0);
    EXPECT_TRUE(same_bits(Kneiphof2025DfgLut::load_or_compute_table(), computed));  // stored
    std::vector<std::filesystem::path> files;
    for (const auto& f : std::filesystem::directory_iterator(dir)) files.push_back(f.path());
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0].filename().string().rfind("kneiphof2025_dfg-", 0), 0u);
    EXPECT_TRUE(same_bits(Kneiphof2025DfgLut::load_or_compute_table(), computed));  // hit
    {
        std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(300);
        f.put('\x7f');
    }
    EXPECT_TRUE(same_bits(Kneiphof2025DfgLut::load_or_compute_table(), computed));  // recomputed
    EXPECT_TRUE(same_bits(Kneiphof2025DfgLut::load_or_compute_table(), computed));  // hit again
    std::filesystem::remove_all(dir);
    ::unsetenv("GLINTLAB_CACHE_DIR");
    ::setenv("GLINTLAB_NO_CACHE", "1", 1);
}

}  // namespace
}  // namespace glintlab
