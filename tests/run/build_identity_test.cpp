// Which build made a result: the code files are found from the process itself, so that
// beachball's own shared libraries (the loader, every force term) are among them without a
// list of names, and the digest of the code is the same each time it is asked for.
#include "run/build_identity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace bb {
namespace {

namespace fs = std::filesystem;

TEST(BuildIdentity, TheProjectsLibrariesAreFoundFromTheProcess) {
  // This test program links them from the folder of the beachball program.
  const fs::path bin = fs::path(BEACHBALL_PROGRAM).parent_path();
  const std::vector<std::string> files = loaded_code_files();
  ASSERT_FALSE(files.empty());
  EXPECT_EQ(files.front(), "/proc/self/exe");
  for (const char* library : {"libbb_model.so", "libbb_study.so", "libbb_physics.so"}) {
    const std::string path = fs::canonical(bin / library).string();
    EXPECT_NE(std::find(files.begin(), files.end(), path), files.end()) << path;
  }
  EXPECT_EQ(shared_code_digest().size(), 32u);
  EXPECT_EQ(shared_code_digest(), shared_code_digest());
  EXPECT_EQ(build_digest(), build_digest());
  EXPECT_NE(build_digest(), shared_code_digest());
}

}  // namespace
}  // namespace bb
