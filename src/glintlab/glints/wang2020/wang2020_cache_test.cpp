// wang2020's DPF tables through the on-disk cache: a cache hit returns the
// freshly built tables bit for bit, a corrupt file is rebuilt, and the key
// follows the resolution. Small 6 × 6 × 12 tables (~0.1 s to build).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "glintlab/core/disk_cache.h"
#include "glintlab/glints/wang2020/wang2020_dpf.h"

namespace glintlab::wang2020 {
namespace {

void expect_same(const DpfSet& a, const DpfSet& b) {
    for (size_t r = 0; r < kRoughnessSet.size(); ++r)
        EXPECT_EQ(a.tables[r].values(), b.tables[r].values()) << r;
}

TEST(Wang2020Cache, HitEqualsFreshBuildAndCorruptFileIsRebuilt) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("glintlab_wang2020_cache_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    ::setenv("GLINTLAB_CACHE_DIR", dir.c_str(), 1);
    ::unsetenv("GLINTLAB_NO_CACHE");
    const DpfResolution res{6, 6, 12};
    const DpfSet fresh = load_or_build_dpf_set(res);
    // Exactly one cache file, for this table.
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir)) files.push_back(e.path());
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0].filename().string().rfind("wang2020_dpf-", 0), 0u);
    const DpfSet hit = load_or_build_dpf_set(res);
    expect_same(fresh, hit);
    // The fresh build equals the tables generated directly.
    EXPECT_EQ(fresh.tables[3].values(),
              generate_dpf_table(kRoughnessSet[3], fresh.gamma_rad, res).values());
    // Corrupt a byte: the file is not trusted, the set rebuilt (equal) and stored again.
    {
        std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(200);
        f.put('\x7f');
    }
    const DpfSet rebuilt = load_or_build_dpf_set(res);
    expect_same(fresh, rebuilt);
    expect_same(fresh, load_or_build_dpf_set(res));
    // The extracted table for a material (α, γ): the cached copy equals
    // extract_dpf bit for bit, fresh and on a hit (a second file).
    const DpfTable direct = extract_dpf(fresh, 0.3, 0.1);
    EXPECT_EQ(load_or_extract_dpf(fresh, 0.3, 0.1).values(), direct.values());
    EXPECT_EQ(load_or_extract_dpf(fresh, 0.3, 0.1).values(), direct.values());
    // Another resolution is another key (a third file).
    load_or_build_dpf_set(DpfResolution{6, 6, 14});
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) n += e.is_regular_file();
    EXPECT_EQ(n, 3);
    std::filesystem::remove_all(dir);
    ::unsetenv("GLINTLAB_CACHE_DIR");
}

}  // namespace
}  // namespace glintlab::wang2020
