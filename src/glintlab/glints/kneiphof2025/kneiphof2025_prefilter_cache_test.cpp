// kneiphof2025's prefiltered maps through the on-disk table cache: a hit is
// the constructed environment bit for bit (whatever the map's rotation), the
// key changes with any pixel, the scale and every option, and a corrupt,
// truncated or wrongly sized file is rejected, removed and rebuilt.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>

#include "glintlab/core/disk_cache.h"
#include "glintlab/core/disk_cache_test_util.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"
#include "glintlab/scene/environment.h"

namespace glintlab {
namespace {

template <typename T>
bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_levels(const std::vector<Kneiphof2025Level>& a, const std::vector<Kneiphof2025Level>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].width != b[i].width || a[i].height != b[i].height ||
            a[i].data.size() != b[i].data.size() ||
            std::memcmp(a[i].data.data(), b[i].data.data(), a[i].data.size() * sizeof(float)) != 0)
            return false;
    return true;
}

// Every member, and lookups (which use the rotation), bit for bit.
void expect_same(const Kneiphof2025Environment& a, const Kneiphof2025Environment& b) {
    EXPECT_EQ(a.levels(), b.levels());
    EXPECT_TRUE(same_bits(a.radiance_levels(), b.radiance_levels()));
    EXPECT_TRUE(same_bits(a.min_luminance(), b.min_luminance()));
    EXPECT_TRUE(same_bits(a.max_luminance(), b.max_luminance()));
    EXPECT_TRUE(same_levels(a.mips(), b.mips()));
    EXPECT_TRUE(same_levels(a.source_mips(), b.source_mips()));
    const Kneiphof2025Sources &sa = a.sources(), &sb = b.sources();
    ASSERT_EQ(sa.directions.size(), sb.directions.size());
    for (size_t k = 0; k < sa.directions.size(); ++k) {
        EXPECT_TRUE(same_bits(sa.directions[k], sb.directions[k]));
        EXPECT_TRUE(same_bits(sa.map_directions[k], sb.map_directions[k]));
        EXPECT_TRUE(same_bits(sa.powers[k], sb.powers[k]));
        EXPECT_TRUE(same_bits(sa.radii[k], sb.radii[k]));
    }
    EXPECT_TRUE(same_bits(sa.color, sb.color));
    for (const glm::vec3 d : {glm::vec3(0.3f, 0.8f, -0.5f), glm::vec3(-0.7f, 0.1f, 0.7f)})
        for (const float r : {0.0f, 0.4f, 1.0f})
            EXPECT_TRUE(same_bits(a.fetch_radiance_sources(glm::normalize(d), r),
                                  b.fetch_radiance_sources(glm::normalize(d), r)));
}

// A small sky with a bright compact sun (a source of Kneiphof2025Sources).
Image sky() {
    Image img(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x)
            img.at(x, y) = glm::vec3(0.2f + 0.01f * x, 0.3f, y < 16 ? 0.6f : 0.05f);
    img.at(20, 8) = img.at(21, 8) = glm::vec3(4000.0f, 3800.0f, 3500.0f);
    return img;
}

Kneiphof2025PrefilterOptions small_options() {
    Kneiphof2025PrefilterOptions o;
    o.levels = 4;
    o.base_width = 32;
    o.mip_count = 3;
    o.samples = 8;
    return o;
}

std::vector<std::filesystem::path> files_in(const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& f : std::filesystem::directory_iterator(dir, ec)) files.push_back(f.path());
    return files;
}

class Kneiphof2025PrefilterCache : public testing::TempDiskCacheTest {};

TEST_F(Kneiphof2025PrefilterCache, HitEqualsBuiltAndBadFilesAreRebuilt) {
    const EnvironmentMap env(sky(), 1.5f, 30.0f);
    const Kneiphof2025PrefilterOptions o = small_options();
    const Kneiphof2025Environment built(env, o);
    ASSERT_FALSE(built.sources().empty());
    bool hit = true;
    expect_same(*Kneiphof2025Environment::load_or_build(env, o, &hit), built);  // stored
    EXPECT_FALSE(hit);
    const std::vector<std::filesystem::path> files = files_in(dir_);
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0], disk_cache_file(Kneiphof2025Environment::kCacheName,
                                        Kneiphof2025Environment::cache_key(env, o)));
    expect_same(*Kneiphof2025Environment::load_or_build(env, o, &hit), built);  // hit
    EXPECT_TRUE(hit);

    // The same image at another rotation shares the file; the lookups and
    // the sources' world directions follow the rotation.
    const EnvironmentMap turned(sky(), 1.5f, -75.0f);
    const Kneiphof2025Environment built_turned(turned, o);
    EXPECT_FALSE(same_bits(built_turned.sources().directions[0], built.sources().directions[0]));
    expect_same(*Kneiphof2025Environment::load_or_build(turned, o, &hit), built_turned);
    EXPECT_TRUE(hit);
    EXPECT_EQ(files_in(dir_).size(), 1u);

    // One byte changed (checksum mismatch): rejected, removed, rebuilt.
    {
        std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(400);
        f.put('\x7f');
    }
    expect_same(*Kneiphof2025Environment::load_or_build(env, o, &hit), built);
    EXPECT_FALSE(hit);
    expect_same(*Kneiphof2025Environment::load_or_build(env, o, &hit), built);
    EXPECT_TRUE(hit);

    // Truncated (size mismatch).
    std::filesystem::resize_file(files[0], std::filesystem::file_size(files[0]) / 2);
    expect_same(*Kneiphof2025Environment::load_or_build(env, o, &hit), built);
    EXPECT_FALSE(hit);

    // A well-formed file whose maps have other sizes than the options imply
    // (here: one level fewer): rejected with a warning, removed, rebuilt.
    Kneiphof2025PrefilterOptions fewer = o;
    fewer.mip_count = o.mip_count - 1;
    (void)Kneiphof2025Environment::load_or_build(env, fewer);
    const uint64_t key = Kneiphof2025Environment::cache_key(env, o);
    const auto other = disk_cache_load(Kneiphof2025Environment::kCacheName,
                                       Kneiphof2025Environment::cache_key(env, fewer));
    ASSERT_TRUE(other.has_value());
    ASSERT_TRUE(disk_cache_store(Kneiphof2025Environment::kCacheName, key, *other));
    ::testing::internal::CaptureStderr();
    expect_same(*Kneiphof2025Environment::load_or_build(env, o, &hit), built);
    EXPECT_NE(::testing::internal::GetCapturedStderr().find("is rejected"), std::string::npos);
    EXPECT_FALSE(hit);
    expect_same(*Kneiphof2025Environment::load_or_build(env, o, &hit), built);
    EXPECT_TRUE(hit);
}

TEST_F(Kneiphof2025PrefilterCache, KeyDependsOnEveryInput) {
    const Kneiphof2025PrefilterOptions o = small_options();
    const EnvironmentMap env(sky(), 1.0f, 0.0f);
    const uint64_t k0 = Kneiphof2025Environment::cache_key(env, o);
    EXPECT_EQ(Kneiphof2025Environment::cache_key(EnvironmentMap(sky(), 1.0f, 0.0f), o), k0);
    // The rotation enters at lookup only (the maps are in the map's frame).
    EXPECT_EQ(Kneiphof2025Environment::cache_key(EnvironmentMap(sky(), 1.0f, 45.0f), o), k0);
    std::set<uint64_t> keys{k0};
    Image one_pixel = sky();
    one_pixel.at(40, 20).y = std::nextafter(one_pixel.at(40, 20).y, 1.0f);
    keys.insert(Kneiphof2025Environment::cache_key(EnvironmentMap(one_pixel, 1.0f, 0.0f), o));
    Image tall(32, 64, glm::vec3(0.5f)), wide(64, 32, glm::vec3(0.5f));
    keys.insert(Kneiphof2025Environment::cache_key(EnvironmentMap(tall, 1.0f, 0.0f), o));
    keys.insert(Kneiphof2025Environment::cache_key(EnvironmentMap(wide, 1.0f, 0.0f), o));
    keys.insert(Kneiphof2025Environment::cache_key(EnvironmentMap(sky(), 2.0f, 0.0f), o));
    int expected = 5;
    auto with = [&](auto set) {
        Kneiphof2025PrefilterOptions p = o;
        set(p);
        keys.insert(Kneiphof2025Environment::cache_key(env, p));
        ++expected;
    };
    with([](auto& p) { p.levels = 8; });
    with([](auto& p) { p.black_level = 2e-2f; });
    with([](auto& p) { p.base_width = 64; });
    with([](auto& p) { p.mip_count = 4; });
    with([](auto& p) { p.samples = 9; });
    EXPECT_EQ(keys.size(), size_t(expected));
}

TEST_F(Kneiphof2025PrefilterCache, OffWritesNothing) {
    ::setenv("GLINTLAB_NO_CACHE", "1", 1);
    const EnvironmentMap env(sky(), 1.0f, 0.0f);
    bool hit = true;
    expect_same(*Kneiphof2025Environment::load_or_build(env, small_options(), &hit),
                Kneiphof2025Environment(env, small_options()));
    EXPECT_FALSE(hit);
    EXPECT_TRUE(files_in(dir_).empty());
}

}  // namespace
}  // namespace glintlab
