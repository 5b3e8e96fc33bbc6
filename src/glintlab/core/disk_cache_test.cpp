#include "glintlab/core/disk_cache.h"
#include "glintlab/core/disk_cache_test_util.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>

namespace glintlab {
namespace {

// Each test gets its own cache directory (pid + test name), so that parallel
// ctest processes never share files, and the cache enabled in it.
class DiskCacheTest : public testing::TempDiskCacheTest {};

std::vector<unsigned char> payload() {
    std::vector<unsigned char> p(10000);
    for (size_t i = 0; i < p.size(); ++i) p[i] = static_cast<unsigned char>(i * 37 + 11);
    return p;
}

TEST_F(DiskCacheTest, StoreThenLoadReturnsTheSameBytes) {
    EXPECT_EQ(disk_cache_dir(), dir_);
    EXPECT_FALSE(disk_cache_load("t", 42).has_value());
    ASSERT_TRUE(disk_cache_store("t", 42, payload()));
    EXPECT_TRUE(std::filesystem::exists(disk_cache_file("t", 42)));
    EXPECT_EQ(disk_cache_load("t", 42), payload());
    EXPECT_FALSE(disk_cache_load("t", 43).has_value());  // another key, another file
    // No temporary file is left behind.
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir_)) files += e.is_regular_file();
    EXPECT_EQ(files, 1);
}

// A payload the table's parser refuses: disk_cache_reject warns, naming the
// file and the reason, and removes it.
TEST_F(DiskCacheTest, RejectWarnsAndRemoves) {
    ASSERT_TRUE(disk_cache_store("t", 9, payload()));
    ::testing::internal::CaptureStderr();
    disk_cache_reject("t", 9, "sizes do not match");
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find(disk_cache_file("t", 9).string()), std::string::npos);
    EXPECT_NE(err.find("sizes do not match"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(disk_cache_file("t", 9)));
    EXPECT_FALSE(disk_cache_load("t", 9).has_value());
}

// A flipped payload byte (checksum), a truncated file (size) and a foreign
// header are never trusted: load returns nothing and removes the file.
TEST_F(DiskCacheTest, CorruptOrTruncatedFilesAreRejectedAndRemoved) {
    const auto file = disk_cache_file("t", 7);
    for (int kind = 0; kind < 3; ++kind) {
        ASSERT_TRUE(disk_cache_store("t", 7, payload()));
        const auto size = std::filesystem::file_size(file);
        if (kind == 0) {
            std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
            f.seekp(std::streamoff(size - 100));
            f.put('\x5a');
        } else if (kind == 1) {
            std::filesystem::resize_file(file, size - 1);
        } else {
            std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
            f.seekp(0);
            f.put('X');
        }
        EXPECT_FALSE(disk_cache_load("t", 7).has_value()) << kind;
        EXPECT_FALSE(std::filesystem::exists(file)) << kind;
    }
}

// A FIFO at an entry's path used to block the load forever (an open for
// reading waits for a writer); a directory there was "corrupt". Either is a
// miss with a warning; the store then replaces the FIFO (rename) and fails
// with a warning on the directory, and nothing blocks.
TEST_F(DiskCacheTest, NonRegularEntriesAreMissesNotBlocks) {
    const auto fifo = disk_cache_file("t", 5);
    std::filesystem::create_directories(fifo.parent_path());
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    ::testing::internal::CaptureStderr();
    EXPECT_FALSE(disk_cache_load("t", 5).has_value());
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("not a regular file"), std::string::npos) << err;
    ASSERT_TRUE(disk_cache_store("t", 5, payload()));
    EXPECT_TRUE(std::filesystem::is_regular_file(fifo));
    EXPECT_EQ(disk_cache_load("t", 5), payload());

    const auto dir = disk_cache_file("t", 6);
    std::filesystem::create_directory(dir);
    ::testing::internal::CaptureStderr();
    EXPECT_FALSE(disk_cache_load("t", 6).has_value());
    EXPECT_FALSE(disk_cache_store("t", 6, payload()));
    (void)::testing::internal::GetCapturedStderr();
    EXPECT_TRUE(std::filesystem::is_directory(dir));
}

TEST_F(DiskCacheTest, DisabledByEnvironmentOrFlag) {
    ::setenv("GLINTLAB_NO_CACHE", "1", 1);
    EXPECT_FALSE(disk_cache_enabled());
    EXPECT_FALSE(disk_cache_store("t", 1, payload()));
    ::unsetenv("GLINTLAB_NO_CACHE");
    set_disk_cache_enabled(false);
    EXPECT_FALSE(disk_cache_store("t", 1, payload()));
    set_disk_cache_enabled(true);
    EXPECT_TRUE(disk_cache_store("t", 1, payload()));
}

// The key depends on every input: values, names, versions and file content
// (not the file's path).
TEST_F(DiskCacheTest, KeyChangesWithEveryInput) {
    const uint64_t base = CacheKey("dpf", 1).add(90).add(0.5).value();
    EXPECT_EQ(CacheKey("dpf", 1).add(90).add(0.5).value(), base);
    EXPECT_NE(CacheKey("dpf", 2).add(90).add(0.5).value(), base);
    EXPECT_NE(CacheKey("dpg", 1).add(90).add(0.5).value(), base);
    EXPECT_NE(CacheKey("dpf", 1).add(91).add(0.5).value(), base);
    EXPECT_NE(CacheKey("dpf", 1).add(90).add(0.25).value(), base);
    std::filesystem::create_directories(dir_);
    const auto a = dir_ / "a.bin", b = dir_ / "b.bin";
    std::ofstream(a) << "environment map";
    std::ofstream(b) << "environment map";
    const uint64_t ka = CacheKey("env", 1).add_file(a).value();
    EXPECT_EQ(CacheKey("env", 1).add_file(b).value(), ka);
    std::ofstream(b) << "environment map!";
    EXPECT_NE(CacheKey("env", 1).add_file(b).value(), ka);
}

}  // namespace
}  // namespace glintlab

namespace glintlab {
namespace {

// A payload's vectors round-trip, an empty one too (its data() may be null:
// the reader must not pass it to memcpy, which UBSan reports), and a count
// past the payload's end is refused.
TEST(ByteReaderWriter, VectorsRoundTripEmptyOrNot) {
    ByteWriter out;
    out.put_vector(std::vector<float>{});
    out.put_vector(std::vector<float>{1.5f, -2.0f});
    out.put(uint32_t(7));
    ByteReader in(out.bytes);
    std::vector<float> empty{3.0f}, two;
    uint32_t seven = 0;
    ASSERT_TRUE(in.get_vector(empty));
    EXPECT_TRUE(empty.empty());
    ASSERT_TRUE(in.get_vector(two));
    EXPECT_EQ(two, (std::vector<float>{1.5f, -2.0f}));
    ASSERT_TRUE(in.get(seven));
    EXPECT_EQ(seven, 7u);
    EXPECT_TRUE(in.at_end());

    ByteWriter bad;
    bad.put(uint64_t(1000));  // 1000 floats announced, none follow
    ByteReader short_in(bad.bytes);
    std::vector<float> v;
    EXPECT_FALSE(short_in.get_vector(v));
}

}  // namespace
}  // namespace glintlab
