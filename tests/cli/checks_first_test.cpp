// Mistakes found before any backend runs: a case name over the limit and an --out that
// cannot be written are refused at once (exit 2, the limit or the OS's reason named),
// though the case would otherwise run for tens of seconds, and nothing is created.
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// `beachball ARGS` and how long it took, in seconds.
std::pair<test::Outcome, double> timed(const std::string& args) {
  const Clock::time_point begun = Clock::now();
  test::Outcome o = test::beachball(args);
  return {o, std::chrono::duration<double>(Clock::now() - begun).count()};
}

/// A folder nobody may write: a read-only tmpfs for root (whom permissions do not stop),
/// a folder without write permission for anyone else.
struct ReadOnlyFolder {
  std::string path = test::fresh_dir("read_only");
  std::string reason;  ///< what the OS says when writing there
  ReadOnlyFolder() {
    fs::create_directories(path);
    if (geteuid() != 0) {
      chmod(path.c_str(), 0555);
      reason = "Permission denied";
    } else if (mount("tmpfs", path.c_str(), "tmpfs", MS_RDONLY, "size=64k") == 0) {
      mounted = true;
      reason = "Read-only file system";
    }
  }
  ~ReadOnlyFolder() {
    if (mounted) umount(path.c_str());
    chmod(path.c_str(), 0755);
  }
  bool mounted = false;
};

TEST(ChecksFirst, ACaseNameOverSixtyFourCharactersIsRefusedAtOnce) {
  const std::string dir = test::fresh_dir("long_name");
  // "name" is on line 2.
  const std::string file =
      test::write_case(dir, "case.toml", "\n" + test::slow_case(std::string(250, 'n')));
  for (const char* command : {"run", "report", "stability"}) {
    const auto [o, seconds] = timed(std::string(command) + " " + file + " --out " + dir + "/out");
    EXPECT_EQ(o.exit_code, 2) << command << ": " << o.out;
    EXPECT_NE(o.out.find(file + ":2: 'name' is 250 characters long; a case name may be at most 64"),
              std::string::npos)
        << o.out;
    EXPECT_LT(seconds, 1.0) << command;
    EXPECT_FALSE(fs::exists(dir + "/out")) << command;
  }
}

TEST(ChecksFirst, AnOutFolderThatCannotBeWrittenIsRefusedAtOnceWithTheOsReason) {
  const ReadOnlyFolder read_only;
  if (read_only.reason.empty()) GTEST_SKIP() << "root without the right to mount a tmpfs";
  const std::string dir = test::fresh_dir("checks_first_out");
  const std::string file = test::write_case(dir, "slow.toml", test::slow_case("slow"));
  // The folder itself, and a new folder inside it.
  for (const std::string& out : {read_only.path, read_only.path + "/new"}) {
    for (const char* command : {"run", "report", "stability"}) {
      const auto [o, seconds] = timed(std::string(command) + " " + file + " --out " + out);
      EXPECT_EQ(o.exit_code, 2) << command << " " << out << ": " << o.out;
      EXPECT_NE(o.out.find(out + ": cannot"), std::string::npos) << o.out;
      EXPECT_NE(o.out.find(read_only.reason), std::string::npos) << o.out;
      EXPECT_LT(seconds, 1.0) << command << " " << out;
      EXPECT_TRUE(fs::is_empty(read_only.path)) << command << " " << out;
    }
  }
}

}  // namespace
}  // namespace bb
