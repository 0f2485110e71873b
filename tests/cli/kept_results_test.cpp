// Only what changed runs again: a second `run` of the same cases reuses every kept result
// and writes the same bytes; a case whose text changed runs again while the others are
// reused; --fresh runs everything; a report reuses the accuracy runs, the stability trials
// and a sweep's points, and writes the same report; a run of some of the steps is the same
// bytes as a fresh one; a folder that cannot keep results is said.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

TEST(KeptResults, OnlyTheCaseThatChangedRunsAgain) {
  const std::string dir = test::fresh_dir("kept_results");
  const std::string cache = dir + "/cache";
  const std::string a = test::write_case(dir, "a.toml", test::minimal_case("a"));
  const std::string b = test::write_case(dir, "b.toml", test::minimal_case("b"));
  const auto run = [&](const std::string& out, const std::string& more = "") {
    return test::beachball("run " + a + " " + b +
                           " --no-cost --backends reference,course/rk4,course/explicit-euler "
                           "--out " +
                           dir + "/" + out + " --cache " + cache + more);
  };
  const test::Outcome first = run("first");
  ASSERT_EQ(first.exit_code, 0) << first.out;
  const auto [none, all] = test::kept_counts(first.out);
  EXPECT_EQ(none, 0) << first.out;
  ASSERT_GT(all, 0) << first.out;
  ASSERT_EQ(all % 2, 0) << "the two cases run alike";

  const test::Outcome second = run("second");
  ASSERT_EQ(second.exit_code, 0) << second.out;
  EXPECT_EQ(test::kept_counts(second.out), std::make_pair(all, 0)) << second.out;
  EXPECT_EQ(test::snapshot(dir + "/second"), test::snapshot(dir + "/first"));

  // a's text changes (its duration): a runs again, b is reused.
  std::string text = test::minimal_case("a");
  text.replace(text.find("duration = 1.0"), 14, "duration = 2.0");
  test::write_case(dir, "a.toml", text);
  const test::Outcome edited = run("edited");
  ASSERT_EQ(edited.exit_code, 0) << edited.out;
  EXPECT_EQ(test::kept_counts(edited.out), std::make_pair(all / 2, all / 2)) << edited.out;
  EXPECT_EQ(test::bytes(dir + "/edited/b.json"), test::bytes(dir + "/first/b.json"));
  EXPECT_NE(test::bytes(dir + "/edited/a.json"), test::bytes(dir + "/first/a.json"));

  const test::Outcome fresh = run("fresh", " --fresh");
  EXPECT_EQ(test::kept_counts(fresh.out), std::make_pair(0, all)) << fresh.out;
  EXPECT_EQ(test::bytes(dir + "/fresh/b.json"), test::bytes(dir + "/first/b.json"));

  // Without a folder of kept results (the tests' environment says off), nothing is said.
  const test::Outcome off = test::beachball("run " + b + " --no-cost --out " + dir + "/off");
  EXPECT_EQ(test::kept_counts(off.out), std::make_pair(-1, -1)) << off.out;
}

TEST(KeptResults, AReportReusesItsRunsTrialsAndSweepAndWritesTheSameReport) {
  const std::string dir = test::fresh_dir("kept_report");
  const std::string cache = dir + "/cache";
  const std::string stack = test::write_case(dir, "stack.toml", test::kStackedBalls);
  const std::string a = test::write_case(dir, "a.toml", test::minimal_case("a"));
  const auto report = [&](const std::string& out) {
    return test::beachball("report " + stack + " " + a + " --no-cost --out " + dir + "/" + out +
                           " --cache " + cache);
  };
  const test::Outcome first = report("first");
  ASSERT_EQ(first.exit_code, 0) << first.out;
  const test::Outcome second = report("second");
  ASSERT_EQ(second.exit_code, 0) << second.out;
  // Everything is reused, the runs of the fallback of docs/design.md too (the stacked balls have no
  // reference: a backend's runs are measured against its own finest one).
  const int all = test::kept_counts(first.out).second;
  EXPECT_GT(all, 0) << first.out;
  EXPECT_EQ(test::kept_counts(second.out), std::make_pair(all, 0)) << second.out;
  auto before = test::snapshot(dir + "/first"), after = test::snapshot(dir + "/second");
  EXPECT_EQ(after, before);
}

// A run of some of the case's steps reuses only what is the same bytes as a fresh run of
// them: without a reference (the stacked balls), a backend's runs are measured against its
// finest run of this selection, not a finer one an earlier run made.
TEST(KeptResults, SomeOfTheStepsGiveTheBytesOfAFreshRunOfThem) {
  const std::string dir = test::fresh_dir("kept_subset");
  const std::string stack = test::write_case(dir, "stack.toml", test::kStackedBalls);
  const auto run = [&](const std::string& out, const std::string& more) {
    return test::beachball("run " + stack +
                           " --no-cost --backends reference,course/rk4,course/explicit-euler "
                           "--out " +
                           dir + "/" + out + more);
  };
  const std::string cache = " --cache " + dir + "/cache";
  ASSERT_EQ(run("all", cache).exit_code, 0);
  const test::Outcome kept_subset = run("kept", " --dt 1/60,1/120" + cache);
  ASSERT_EQ(kept_subset.exit_code, 0) << kept_subset.out;
  // The reference and its self-check are the same whatever the steps: reused.
  EXPECT_GE(test::kept_counts(kept_subset.out).first, 2) << kept_subset.out;
  const test::Outcome fresh_subset = run("fresh", " --dt 1/60,1/120");
  ASSERT_EQ(fresh_subset.exit_code, 0) << fresh_subset.out;
  EXPECT_EQ(test::bytes(dir + "/kept/stack.json"), test::bytes(dir + "/fresh/stack.json"));
  EXPECT_EQ(test::snapshot(dir + "/kept"), test::snapshot(dir + "/fresh"));
}

// A folder of kept results that cannot be used (a file, another user's folder, one that
// cannot be written) is said, and nothing claims results were kept in it.
TEST(KeptResults, AFolderThatCannotBeUsedIsSaid) {
  const std::string dir = test::fresh_dir("kept_unusable");
  const std::string a = test::write_case(dir, "a.toml", test::minimal_case("a"));
  std::ofstream(dir + "/a file") << "not a folder";
  const test::Outcome o =
      test::beachball("run " + a + " --no-cost --out " + dir + "/out --cache '" + dir + "/a file'");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find("cannot be used: it is not a folder"), std::string::npos) << o.out;
  EXPECT_EQ(test::kept_counts(o.out), std::make_pair(-1, -1)) << o.out;
  EXPECT_EQ(test::bytes(dir + "/a file"), "not a folder");
}

// Costs are kept too, but never passed off as fresh: a reused cost says when it was timed
// (in the JSON, on the case's page and on the index), and --fresh times it anew.
TEST(KeptResults, AKeptCostSaysWhenItWasTimed) {
  const std::string dir = test::fresh_dir("kept_costs");
  const std::string a = test::write_case(dir, "a.toml", test::minimal_case("a"));
  const auto report = [&](const std::string& out, const std::string& more = "") {
    return test::beachball("report " + a + " --cost-time 0.001 --out " + dir + "/" + out +
                           " --cache " + dir + "/cache" + more);
  };
  ASSERT_EQ(report("first").exit_code, 0);
  const std::string first = test::bytes(dir + "/first/a.json");
  EXPECT_EQ(first.find("measured_at"), std::string::npos);
  const test::Outcome second = report("second");
  ASSERT_EQ(second.exit_code, 0) << second.out;
  EXPECT_EQ(test::kept_counts(second.out).second, 0) << second.out;
  const std::string json = test::bytes(dir + "/second/a.json");
  // "measured_at": "YYYY-MM-DDTHH:MM:SSZ"
  const auto at = json.find("\"measured_at\": \"");
  ASSERT_NE(at, std::string::npos) << json;
  const std::string when = json.substr(at + 16, 20);
  EXPECT_TRUE(when.size() == 20 && when[4] == '-' && when[10] == 'T' && when[19] == 'Z') << when;
  EXPECT_NE(test::bytes(dir + "/second/a.md").find("Kept costs: the costs of"), std::string::npos);
  EXPECT_NE(test::bytes(dir + "/second/README.md").find("**Kept costs**:"), std::string::npos);
  const test::Outcome fresh = report("fresh", " --fresh");
  ASSERT_EQ(fresh.exit_code, 0) << fresh.out;
  EXPECT_EQ(test::bytes(dir + "/fresh/a.json").find("measured_at"), std::string::npos);
  EXPECT_EQ(test::bytes(dir + "/fresh/README.md").find("Kept costs"), std::string::npos);
}

}  // namespace
}  // namespace bb
