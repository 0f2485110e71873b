// Command-line values outside their stated ranges are refused, naming the option, before
// anything is created.
#include "cli/option_values.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "study/case_error.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(OptionValues, RangesRefuseNonFiniteAndOutOfRangeValues) {
  for (double bad : {0.0, -1.0, 9.3e9, double(INFINITY), double(NAN)})
    EXPECT_THROW(cli::check_range("--timeout", bad, cli::kTimeoutRange), CaseError) << bad;
  EXPECT_NO_THROW(cli::check_range("--timeout", 5.0, cli::kTimeoutRange));
  EXPECT_THROW(cli::check_range("--jobs", 0, cli::kJobsRange), CaseError);
  EXPECT_NO_THROW(cli::check_range("--jobs", 2, cli::kJobsRange));
}

TEST(OptionValues, ListsRefuseEmptyEntries) {
  for (const char* bad : {"", ",", "a,,b", "a,", ",a"})
    EXPECT_THROW(cli::split_list("--backends", bad), CaseError) << bad;
  EXPECT_EQ(cli::split_list("--backends", "a,b"), (std::vector<std::string>{"a", "b"}));
}

TEST(OptionValues, StepsAreFinitePositiveSecondsOrFractions) {
  EXPECT_DOUBLE_EQ(cli::parse_step("1/60"), 1.0 / 60.0);
  EXPECT_DOUBLE_EQ(cli::parse_step("0.01"), 0.01);
  for (const char* bad : {"", "abc", "0", "-1/60", "1/0", "inf", "nan", "1/60x", "1/", "/60"})
    EXPECT_THROW(cli::parse_step(bad), CaseError) << bad;
}

// Every value named in issue 7, through the program: exit 2, the option named, no folder.
TEST(OptionValues, TheProgramRefusesEachBeforeCreatingTheOutputFolder) {
  const std::string drag = test::source_path("cases/drag_fall.toml");
  const struct {
    const char* args;
    const char* named;
  } bad[] = {{"--timeout 9.3e9", "--timeout"},
             {"--timeout inf", "--timeout"},
             {"--timeout 0", "--timeout"},
             {"--timeout nan", "--timeout"},
             {"--cost-time nan", "--cost-time"},
             {"--cost-time 1e9", "--cost-time"},
             {"--jobs 0", "--jobs"},
             {"--jobs -1", "--jobs"},
             {"--dt ''", "--dt"},
             {"--dt 1/20,,", "--dt"},
             {"--backends ''", "--backends"}};
  for (const auto& b : bad) {
    const std::string out = test::fresh_dir("options");
    const test::Outcome o =
        test::beachball("run " + drag + " --no-cost --out " + out + " " + b.args);
    EXPECT_EQ(o.exit_code, 2) << b.args << "\n" << o.out;
    EXPECT_NE(o.out.find(b.named), std::string::npos) << b.args << "\n" << o.out;
    EXPECT_FALSE(std::filesystem::exists(out)) << b.args;
  }
}

TEST(OptionValues, ATrajectoryIsANameAStepAndAFile) {
  const TrajectoryImport t = cli::parse_trajectory_import("my-euler@1/60=out/a=b.csv");
  EXPECT_EQ(t.name, "my-euler");
  EXPECT_DOUBLE_EQ(t.dt, 1.0 / 60.0);
  EXPECT_EQ(t.file, "out/a=b.csv");
  for (const std::string bad : {"mine", "mine@1/60", "@1/60=a.csv", "a/b@1/60=a.csv", "mine@=a.csv",
                                "mine@0=a.csv", "mine@1/60="})
    EXPECT_THROW(cli::parse_trajectory_import(bad), CaseError) << bad;
}

}  // namespace
}  // namespace bb
