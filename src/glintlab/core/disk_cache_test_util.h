// A test fixture with the table cache on, in a directory of its own
// (GLINTLAB_CACHE_DIR) that is removed after each test; ctest turns the
// cache off for every test (GLINTLAB_NO_CACHE=1), which TearDown restores.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "glintlab/core/disk_cache.h"

namespace glintlab::testing {

class TempDiskCacheTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("glintlab_cache_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name() + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir_);
        if (const char* v = std::getenv("GLINTLAB_NO_CACHE")) no_cache_ = v;
        ::setenv("GLINTLAB_CACHE_DIR", dir_.c_str(), 1);
        ::unsetenv("GLINTLAB_NO_CACHE");
        set_disk_cache_enabled(true);
    }
    void TearDown() override {
        std::filesystem::remove_all(dir_);
        ::unsetenv("GLINTLAB_CACHE_DIR");
        if (no_cache_) ::setenv("GLINTLAB_NO_CACHE", no_cache_->c_str(), 1);
    }
    std::filesystem::path dir_;

  private:
    std::optional<std::string> no_cache_;
};

}  // namespace glintlab::testing
