// A full disk loses nothing: a report that cannot be written leaves the previous report
// byte for byte, removes its temporaries and exits 2 with the OS's reason. The test mounts
// a small tmpfs (root, as on CI) and fills it; where it cannot, the same promise is checked
// with a file-size limit, which makes a write fail with the OS's "File too large".
#include <gtest/gtest.h>
#include <sys/mount.h>

#include <filesystem>
#include <fstream>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// A tmpfs of `bytes` mounted for the test's lifetime, at a folder named after the test
/// (ctest runs the tests of this file at once: one's folder must not be another's).
struct SmallDisk {
  std::string path;
  explicit SmallDisk(std::size_t bytes)
      : path(test::fresh_dir(std::string("small_disk_") +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::create_directories(path);
    const std::string options = "size=" + std::to_string(bytes);
    mounted = mount("tmpfs", path.c_str(), "tmpfs", 0, options.c_str()) == 0;
  }
  ~SmallDisk() {
    if (mounted) umount(path.c_str());
  }
  bool mounted = false;
};

/// Fills the disk at `path` until fewer than `left` bytes are free.
void fill(const std::string& path, std::size_t left) {
  const fs::space_info space = fs::space(path);
  std::ofstream(path + "/filler", std::ios::binary)
      << std::string(space.available > left ? space.available - left : 0, 'x');
}

bool has_temporaries(const std::string& folder) {
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (test::beachball_temporary(entry.path().filename().string())) return true;
  return false;
}

TEST(FullDisk, AReportThatCannotBeWrittenLeavesTheOldOneAndExitsTwo) {
  SmallDisk disk(2 << 20);
  if (!disk.mounted) GTEST_SKIP() << "mounting a tmpfs needs root; FileSizeLimit covers this";
  const std::string drag = test::source_path("cases/drag_fall.toml");
  const std::string out = disk.path + "/report";
  const test::Outcome first = test::beachball("report " + drag + " --no-cost --out " + out);
  ASSERT_EQ(first.exit_code, 0) << first.out;
  const auto before = test::snapshot(out);
  ASSERT_GE(before.size(), 5u);

  fill(disk.path, 20 * 1024);
  const test::Outcome full = test::beachball("report " + drag + " --no-cost --out " + out);
  EXPECT_EQ(full.exit_code, 2) << full.out;
  EXPECT_NE(full.out.find("No space left on device"), std::string::npos) << full.out;
  EXPECT_EQ(test::snapshot(out), before) << "the previous report changed";
  EXPECT_FALSE(has_temporaries(disk.path)) << "temporaries were left behind";
}

TEST(FullDisk, ARunIntoANewFolderLeavesNoPartialFile) {
  SmallDisk disk(1 << 20);
  if (!disk.mounted) GTEST_SKIP() << "mounting a tmpfs needs root; FileSizeLimit covers this";
  fill(disk.path, 20 * 1024);
  const std::string out = disk.path + "/run";
  const test::Outcome o = test::beachball("run " + test::source_path("cases/drag_fall.toml") +
                                          " --no-cost --out " + out);
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("No space left on device"), std::string::npos) << o.out;
  // Nothing half-written: the folder holds no output at all.
  if (fs::exists(out)) {
    EXPECT_TRUE(test::snapshot(out).empty());
  }
  EXPECT_FALSE(has_temporaries(disk.path));
}

// A write refused by a file-size limit (SIGXFSZ ignored, so write() returns EFBIG) behaves
// like a full disk: old report intact, temporaries gone, exit 2 with the OS's reason.
TEST(FileSizeLimit, AReportThatCannotBeWrittenLeavesTheOldOneAndExitsTwo) {
  const std::string dir = test::fresh_dir("file_size_limit");
  const std::string drag = test::source_path("cases/drag_fall.toml");
  const std::string out = dir + "/report";
  const test::Outcome first = test::beachball("report " + drag + " --no-cost --out " + out);
  ASSERT_EQ(first.exit_code, 0) << first.out;
  const auto before = test::snapshot(out);

  // 8 blocks of 1024 bytes: smaller than the page, larger than nothing.
  const test::Outcome limited =
      test::beachball("report " + drag + " --no-cost --out " + out, "trap '' XFSZ; ulimit -f 8;");
  EXPECT_EQ(limited.exit_code, 2) << limited.out;
  EXPECT_NE(limited.out.find("File too large"), std::string::npos) << limited.out;
  EXPECT_EQ(test::snapshot(out), before) << "the previous report changed";
  EXPECT_FALSE(has_temporaries(dir)) << "temporaries were left behind";
}

}  // namespace
}  // namespace bb
