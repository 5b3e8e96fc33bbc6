// chermain2020's dictionary through the on-disk cache: a hit returns the
// generated dictionary bit for bit, a corrupt file is rebuilt, and the key
// follows every parameter. A small dictionary (8 marginals x 4 levels, ms).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "glintlab/core/disk_cache.h"
#include "glintlab/glints/chermain2020/dictionary.h"

namespace glintlab {
namespace {

TEST(Chermain2020DictionaryCache, HitEqualsGeneratedAndCorruptFileIsRebuilt) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("glintlab_chermain2020_cache_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    ::setenv("GLINTLAB_CACHE_DIR", dir.c_str(), 1);
    ::unsetenv("GLINTLAB_NO_CACHE");
    DictionaryParams params;
    params.n_dists = 8;
    params.n_levels = 4;
    params.table_size = 16;
    const Dictionary generated = generate_dictionary(params);
    const Dictionary fresh = load_or_generate_dictionary(params);
    EXPECT_EQ(fresh.values, generated.values);
    EXPECT_EQ(fresh.slope_max, generated.slope_max);
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir)) files.push_back(e.path());
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0].filename().string().rfind("chermain2020_dictionary-", 0), 0u);
    const Dictionary hit = load_or_generate_dictionary(params);
    EXPECT_EQ(hit.values, generated.values);
    EXPECT_EQ(hit.slope_max, generated.slope_max);
    // Corrupt a byte of the payload: not trusted, regenerated (equal), stored again.
    {
        std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(100);
        f.put('\x7f');
    }
    EXPECT_EQ(load_or_generate_dictionary(params).values, generated.values);
    EXPECT_EQ(load_or_generate_dictionary(params).values, generated.values);
    // Every parameter is in the key.
    const uint64_t key = dictionary_cache_key(params);
    for (int i = 0; i < 6; ++i) {
        DictionaryParams q = params;
        if (i == 0) q.n_levels += 1;
        if (i == 1) q.n_dists += 1;
        if (i == 2) q.alpha_dict *= 1.01f;
        if (i == 3) q.lobe_sigma *= 1.01f;
        if (i == 4) q.table_size += 1;
        if (i == 5) q.seed += 1;
        EXPECT_NE(dictionary_cache_key(q), key) << i;
    }
    params.seed += 1;
    EXPECT_EQ(load_or_generate_dictionary(params).values, generate_dictionary(params).values);
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) n += e.is_regular_file();
    EXPECT_EQ(n, 2);
    std::filesystem::remove_all(dir);
    ::unsetenv("GLINTLAB_CACHE_DIR");
    ::setenv("GLINTLAB_NO_CACHE", "1", 1);
}

}  // namespace
}  // namespace glintlab
