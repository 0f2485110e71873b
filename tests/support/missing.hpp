// A test that needs something a machine may lack (a Debian package, an engine plugin that was
// not built) skips and says what is missing; where BEACHBALL_REQUIRE_ALL is set (CI, which
// installs everything the README promises) the same test fails instead of skipping.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace bb::test {

/// Whether every package and engine must be there (BEACHBALL_REQUIRE_ALL set and not "0").
inline bool everything_required() {
  const char* value = std::getenv("BEACHBALL_REQUIRE_ALL");
  return value != nullptr && std::string(value) != "0" && std::string(value) != "";
}

}  // namespace bb::test

/// Skips the test when `why` (a std::string, empty when nothing is missing) names something
/// missing, or fails it when everything is required.
#define BB_SKIP_IF_MISSING(why)                                                             \
  do {                                                                                      \
    const std::string bb_missing_ = (why);                                                  \
    if (!bb_missing_.empty()) {                                                             \
      if (::bb::test::everything_required())                                                \
        FAIL() << bb_missing_ << " (BEACHBALL_REQUIRE_ALL is set: nothing may be missing)"; \
      GTEST_SKIP() << bb_missing_;                                                          \
    }                                                                                       \
  } while (0)
