// cache_dir(): $XDG_CACHE_HOME/pdrt, else ~/.cache/pdrt (XDG base directories).
#include "sampling/core/cache_dir.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace pdrt {
namespace {

// Sets an environment variable for one test and restores it after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* v = std::getenv(name)) old_ = v;
    if (value)
      setenv(name, value, 1);
    else
      unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(CacheDir, PrefersXdgCacheHome) {
  ScopedEnv xdg("XDG_CACHE_HOME", "/x/cache"), home("HOME", "/h");
  EXPECT_EQ(cache_dir(), std::filesystem::path("/x/cache/pdrt"));
}

TEST(CacheDir, FallsBackToDotCacheInHome) {
  ScopedEnv xdg("XDG_CACHE_HOME", ""), home("HOME", "/h");
  EXPECT_EQ(cache_dir(), std::filesystem::path("/h/.cache/pdrt"));
}

}  // namespace
}  // namespace pdrt
