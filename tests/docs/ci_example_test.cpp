// The CI matrix examples are copy-paste workflows: every beachball command they run names a
// subcommand and options the program takes, and each matrix runs --shard I/N with N its own
// length. In docs/examples/github-actions-shards.yml the merge takes every shard, once; in
// docs/examples/ci/physics-baseline.yml (a user's repository) each shard checks the cases
// against the committed baseline, with the user's plugin, and writes its JUnit file.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// The words of `line` after "build/bin/beachball", split on spaces, the matrix's shard
/// number written I.
std::vector<std::string> beachball_words(std::string line) {
  const std::string program = "build/bin/beachball ", shard = "${{ matrix.shard }}";
  for (std::size_t at; (at = line.find(shard)) != std::string::npos;)
    line.replace(at, shard.size(), "I");
  const std::size_t at = line.find(program);
  std::vector<std::string> words;
  if (at == std::string::npos) return words;
  std::istringstream rest(line.substr(at + program.size()));
  for (std::string w; rest >> w;) words.push_back(w);
  return words;
}

TEST(CiExample, EveryCommandIsOneTheProgramTakesAndTheShardsAreOneSet) {
  const std::string workflow =
      test::bytes(test::source_path("docs/examples/github-actions-shards.yml"));
  ASSERT_FALSE(workflow.empty());
  std::istringstream lines(workflow);
  int commands = 0, matrices = 0;
  std::set<std::string> merged;
  for (std::string line; std::getline(lines, line);) {
    if (line.find("shard: [1, 2, 3, 4]") != std::string::npos) ++matrices;
    const std::vector<std::string> words = beachball_words(line);
    if (words.empty()) continue;
    ++commands;
    SCOPED_TRACE(line);
    const test::Outcome help = test::beachball(words[0] + " --help");
    ASSERT_EQ(help.exit_code, 0) << help.out;
    for (std::size_t k = 1; k < words.size(); ++k) {
      if (words[k].starts_with("--")) {
        EXPECT_NE(help.out.find(words[k] + " "), std::string::npos) << words[k] << "\n" << help.out;
      }
      if (words[k] == "--shard") {
        ASSERT_LT(k + 1, words.size());
        EXPECT_EQ(words[k + 1], "I/4");
      }
    }
    if (words[0] == "merge") {
      for (std::size_t k = 1; k < words.size() && !words[k].starts_with("--"); ++k)
        EXPECT_TRUE(merged.insert(words[k]).second) << words[k];
    }
  }
  EXPECT_EQ(commands, 3);
  EXPECT_EQ(matrices, 2);
  EXPECT_EQ(merged, (std::set<std::string>{"shard-1", "shard-2", "shard-3", "shard-4"}));
}

TEST(CiExample, TheBaselineWorkflowChecksEveryShardAgainstTheBaseline) {
  const std::string workflow =
      test::bytes(test::source_path("docs/examples/ci/physics-baseline.yml"));
  ASSERT_FALSE(workflow.empty());
  std::istringstream lines(workflow);
  std::vector<std::vector<std::string>> commands;
  for (std::string line; std::getline(lines, line);)
    if (std::vector<std::string> words = beachball_words(line); !words.empty())
      commands.push_back(words);
  ASSERT_EQ(commands.size(), 1u);
  const std::vector<std::string>& words = commands[0];
  EXPECT_NE(workflow.find("shard: [1, 2]"), std::string::npos);
  ASSERT_EQ(words[0], "check");
  const test::Outcome help = test::beachball("check --help");
  ASSERT_EQ(help.exit_code, 0) << help.out;
  std::set<std::string> options;
  for (std::size_t k = 1; k < words.size(); ++k) {
    if (!words[k].starts_with("--")) continue;
    options.insert(words[k]);
    EXPECT_NE(help.out.find(words[k] + " "), std::string::npos) << words[k] << "\n" << help.out;
    ASSERT_LT(k + 1, words.size());
    if (words[k] == "--shard") {
      EXPECT_EQ(words[k + 1], "I/2");
    }
    // The JUnit files the matrix writes are the ones it publishes.
    if (words[k] == "--junit") {
      EXPECT_EQ(words[k + 1], "physics-I.xml");
    }
  }
  EXPECT_EQ(options, (std::set<std::string>{"--plugin", "--baseline", "--shard", "--junit"}));
  EXPECT_NE(workflow.find("report_paths: physics-*.xml"), std::string::npos);
}

}  // namespace
}  // namespace bb
