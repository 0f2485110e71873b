// A report split into shards (`report --shard I/N`, each runnable anywhere) and put back
// together (`merge`) is the same report, byte for byte, as one run unsplit; a merge refuses
// a set with a shard missing or given twice, shards made from other case files, and shards
// that lost a result, before it writes anything; a shard never writes among a user's files.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <sstream>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

struct Split {
  std::string dir, cases;
};

/// Cases split in three: a minimal one and, `with_stack`, one with a sweep and no reference
/// (so DESIGN.md's fallback).
Split split_in_three(const std::string& name, bool with_stack) {
  Split s{test::fresh_dir(name), ""};
  s.cases = test::write_case(s.dir, "a.toml", test::minimal_case("a"));
  if (with_stack) s.cases += " " + test::write_case(s.dir, "stack.toml", test::kStackedBalls);
  for (int i = 1; i <= 3; ++i) {
    const test::Outcome o =
        test::beachball("report " + s.cases + " --no-cost --shard " + std::to_string(i) +
                        "/3 --out " + s.dir + "/shard" + std::to_string(i));
    EXPECT_EQ(o.exit_code, 0) << o.out;
  }
  return s;
}

std::string shards(const Split& s, const std::vector<int>& which) {
  std::string out;
  for (int i : which) out += " " + s.dir + "/shard" + std::to_string(i);
  return out;
}

TEST(Shards, MergedTheyAreTheReportUnsplit) {
  const Split s = split_in_three("shards_merged", true);
  const test::Outcome merged = test::beachball("merge" + shards(s, {3, 1, 2}) + " --cases " +
                                               s.cases + " --out " + s.dir + "/merged");
  ASSERT_EQ(merged.exit_code, 0) << merged.out;
  const test::Outcome whole =
      test::beachball("report " + s.cases + " --no-cost --out " + s.dir + "/whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  const auto a = test::snapshot(s.dir + "/merged"), b = test::snapshot(s.dir + "/whole");
  ASSERT_GT(b.size(), 5u);
  EXPECT_EQ(a, b);
}

// `run --shard I/N` with a selection of backends and steps: merged, the shards are run's
// files unsplit, made with the same selection; a merge refuses shards of two commands.
TEST(Shards, RunShardsMergedAreTheRunUnsplit) {
  const std::string dir = test::fresh_dir("shards_run");
  std::string bouncier = test::kStackedBalls;
  bouncier.replace(bouncier.find("\"stack\""), 7, "\"bouncy\"");
  bouncier.replace(bouncier.find("restitution = 0.5"), 17, "restitution = 0.9");
  const std::string cases = test::write_case(dir, "stack.toml", test::kStackedBalls) + " " +
                            test::write_case(dir, "bouncy.toml", bouncier);
  const std::string selection =
      " --no-cost --backends course/semi-implicit-euler,course/rk4,bullet --dt 1/60,1/120";
  for (int i = 1; i <= 2; ++i) {
    const test::Outcome o =
        test::beachball("run " + cases + selection + " --shard " + std::to_string(i) + "/2 --out " +
                        dir + "/shard" + std::to_string(i));
    ASSERT_EQ(o.exit_code, 0) << o.out;
    EXPECT_NE(o.out.find("run shard"), std::string::npos) << o.out;
    EXPECT_FALSE(fs::exists(dir + "/shard" + std::to_string(i) + "/stack.json"));
  }
  const test::Outcome merged = test::beachball(
      "merge " + dir + "/shard2 " + dir + "/shard1 --cases " + cases + " --out " + dir + "/merged");
  ASSERT_EQ(merged.exit_code, 0) << merged.out;
  const test::Outcome whole =
      test::beachball("run " + cases + selection + " --out " + dir + "/whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  const auto a = test::snapshot(dir + "/merged"), b = test::snapshot(dir + "/whole");
  ASSERT_TRUE(b.count("bouncy.json") && b.count("stack.json")) << whole.out;
  EXPECT_EQ(a, b);
  // A report's shard beside a run's: refused, naming both commands.
  const test::Outcome report =
      test::beachball("report " + cases + " --no-cost --shard 2/2 --out " + dir + "/report2");
  ASSERT_EQ(report.exit_code, 0) << report.out;
  const test::Outcome mixed = test::beachball(
      "merge " + dir + "/shard1 " + dir + "/report2 --cases " + cases + " --out " + dir + "/mixed");
  EXPECT_EQ(mixed.exit_code, 2) << mixed.out;
  EXPECT_NE(mixed.out.find("is a shard of `report"), std::string::npos) << mixed.out;
  EXPECT_FALSE(fs::exists(dir + "/mixed/stack.json"));
}

TEST(Shards, AMergeRefusesAnIncompleteOrForeignSetBeforeItWrites) {
  const Split s = split_in_three("shards_refused", false);
  const auto merge = [&](const std::string& folders, const std::string& cases) {
    return test::beachball("merge" + folders + " --cases " + cases + " --out " + s.dir + "/out");
  };
  const struct {
    std::string folders, cases, says;
  } refused[] = {
      {shards(s, {1, 3}), s.cases, "shard 2/3 is missing"},
      {shards(s, {1, 2, 3, 1}), s.cases, "as another folder given is"},
      {shards(s, {1, 2, 3}), s.cases + " " + test::source_path("cases/arrow.toml"),
       "has no case arrow"},
      {" " + s.dir + "/a.toml", s.cases, "is not a shard's folder"},
  };
  for (const auto& r : refused) {
    const test::Outcome o = merge(r.folders, r.cases);
    EXPECT_EQ(o.exit_code, 2) << o.out;
    EXPECT_NE(o.out.find(r.says), std::string::npos) << o.out;
  }
  // Another text of a case: a comment added to a.toml after the shards ran.
  test::write_case(s.dir, "a.toml", test::minimal_case("a") + "\n# edited\n");
  test::Outcome o = merge(shards(s, {1, 2, 3}), s.cases);
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("another text of case a"), std::string::npos) << o.out;
  test::write_case(s.dir, "a.toml", test::minimal_case("a"));
  // A shard that lost its results (the reference's, which every shard keeps, among them).
  for (const auto& entry : fs::directory_iterator(s.dir + "/shard2"))
    if (entry.path().extension() == ".entry") fs::remove(entry.path());
  o = merge(shards(s, {1, 2, 3}), s.cases);
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("hold no result for a run"), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(s.dir + "/out/README.md"));
}

TEST(Shards, AShardNeverWritesAmongAUsersFiles) {
  const std::string dir = test::fresh_dir("shards_user");
  const std::string a = test::write_case(dir, "a.toml", test::minimal_case("a"));
  test::write_case(dir + "/mine", "thesis.txt", "my thesis");
  const test::Outcome o =
      test::beachball("report " + a + " --no-cost --shard 1/2 --out " + dir + "/mine");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("holds thesis.txt"), std::string::npos) << o.out;
  EXPECT_EQ(test::snapshot(dir + "/mine").size(), 1u);
  for (const char* bad : {"0/3", "4/3", "1/0", "a/b", "1/", "2"}) {
    const test::Outcome b = test::beachball("report " + a + " --shard " + bad + " --out " + dir);
    EXPECT_EQ(b.exit_code, 2) << bad << b.out;
    EXPECT_NE(b.out.find("--shard"), std::string::npos) << b.out;
  }
}

// A CI matrix checks the gates in shares: `check --shard I/N` over every I checks each gate
// of the suite exactly once, with the verdict the whole check gives.
TEST(Shards, CheckSharesTheGatesOnceEach) {
  const std::string cases =
      test::source_path("cases/arrow.toml") + " " + test::source_path("cases/equal_masses.toml");
  const auto gate_lines = [](const std::string& out) {
    std::multiset<std::string> lines;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("ok ", 0) == 0 || line.rfind("FAIL ", 0) == 0) lines.insert(line);
    return lines;
  };
  const test::Outcome whole = test::beachball("check " + cases);
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  std::multiset<std::string> shared;
  for (int i = 1; i <= 3; ++i) {
    const test::Outcome part =
        test::beachball("check " + cases + " --shard " + std::to_string(i) + "/3");
    ASSERT_EQ(part.exit_code, 0) << part.out;
    for (const std::string& line : gate_lines(part.out)) shared.insert(line);
  }
  EXPECT_GT(gate_lines(whole.out).size(), 3u);
  EXPECT_EQ(shared, gate_lines(whole.out));
}

}  // namespace
}  // namespace bb
