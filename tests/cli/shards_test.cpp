// A report split into shards (`report --shard I/N`, each runnable anywhere) and put back
// together (`merge`) is the same report, byte for byte, as one run unsplit; a merge refuses
// a set with a shard missing or given twice, shards made from other case files, and shards
// that lost a result or hold a damaged one, before it writes anything (naming the shard,
// the case and the run); a shard keeps a run that timed out, for the merge to show it; a
// shard never writes among a user's files.
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
/// (so the fallback of docs/design.md).
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
  // A shard that lost its results (the reference's, which every shard keeps, among them):
  // the error names the shard, the case and the run, and leaves no --out.
  std::string lost;
  for (int i = 1; i <= 3 && lost.empty(); ++i) {
    const std::string dir = s.dir + "/shard" + std::to_string(i);
    if (std::distance(fs::directory_iterator(dir), fs::directory_iterator()) < 4) continue;
    lost = dir;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.path().extension() == ".entry") fs::remove(entry.path());
  }
  ASSERT_FALSE(lost.empty());
  o = merge(shards(s, {1, 2, 3}), s.cases);
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("case a: no shard holds the result of"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find(lost + ": "), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(s.dir + "/out"));
}

// A run that ended in a timeout (or a crash, or an error) is kept by its shard, so that the
// merge gives what the run unsplit gives; its folder run again runs it again.
TEST(Shards, AMergeKeepsARunThatTimedOut) {
  const std::string dir = test::fresh_dir("shards_timeout");
  const std::string slow = test::write_case(dir, "slow.toml", test::slow_case("slow"));
  // Every run takes seconds, far past the limit: each times out.
  const std::string selection =
      " --no-cost --backends course/rk4,course/explicit-euler --timeout 0.05";
  for (int i = 1; i <= 2; ++i) {
    const test::Outcome o =
        test::beachball("run " + slow + selection + " --shard " + std::to_string(i) + "/2 --out " +
                        dir + "/shard" + std::to_string(i));
    ASSERT_EQ(o.exit_code, 0) << o.out;
  }
  const test::Outcome merged = test::beachball(
      "merge " + dir + "/shard1 " + dir + "/shard2 --cases " + slow + " --out " + dir + "/merged");
  ASSERT_EQ(merged.exit_code, 0) << merged.out;
  const test::Outcome whole =
      test::beachball("run " + slow + selection + " --out " + dir + "/whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  const std::string json = test::bytes(dir + "/whole/slow.json");
  EXPECT_NE(json.find("\"status\": \"timeout\""), std::string::npos) << json;
  EXPECT_EQ(test::snapshot(dir + "/merged"), test::snapshot(dir + "/whole"));
}

// A damaged entry of a later case stops a merge of run's shards before it writes the cases
// before it: every entry is checked first, and the message names the shard and the entry.
TEST(Shards, ADamagedEntryStopsAMergeBeforeItWritesAnything) {
  const std::string dir = test::fresh_dir("shards_damaged");
  const std::string a = test::write_case(dir, "a.toml", test::minimal_case("a"));
  const std::string b = test::write_case(dir, "b.toml", test::minimal_case("b"));
  const std::string selection = " --no-cost --backends course/rk4";
  const auto shard = [&](const std::string& cases, int i) {
    return test::beachball("run " + cases + selection + " --shard " + std::to_string(i) +
                           "/2 --out " + dir + "/shard" + std::to_string(i));
  };
  // The entries of case a, then those that case b adds.
  std::set<std::string> of_a;
  for (int i = 1; i <= 2; ++i) {
    ASSERT_EQ(shard(a, i).exit_code, 0);
    for (const auto& entry : fs::directory_iterator(dir + "/shard" + std::to_string(i)))
      of_a.insert(entry.path().string());
  }
  for (int i = 1; i <= 2; ++i) ASSERT_EQ(shard(a + " " + b, i).exit_code, 0);
  std::string damaged;
  for (int i = 1; i <= 2; ++i)
    for (const auto& entry : fs::directory_iterator(dir + "/shard" + std::to_string(i)))
      if (entry.path().extension() == ".entry" && !of_a.count(entry.path().string())) {
        fs::resize_file(entry.path(), fs::file_size(entry.path()) - 1);
        damaged = entry.path().filename().string();
      }
  ASSERT_FALSE(damaged.empty());
  const test::Outcome o = test::beachball("merge " + dir + "/shard1 " + dir + "/shard2 --cases " +
                                          a + " " + b + " --out " + dir + "/out");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_NE(o.out.find("that are not whole"), std::string::npos) << o.out;
  EXPECT_FALSE(fs::exists(dir + "/out")) << "the merge wrote case a first";
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
