// `check --baseline DIR` end to end: a case run into DIR and checked against it unchanged
// passes; with the baseline's error halved (the run now twice as bad) it fails naming the
// backend, the dt, the metric, both values and the ratio, in the text and in the JUnit file;
// with the baseline made worse it passes and says better; the case's [baseline] tolerance
// changes the verdict; a baseline that is not results is bad input, with nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "model/text.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

using test::beachball;
using test::Outcome;

const char* kBackends = "course/explicit-euler,course/rk4";

/// The minimal case with two observables (one with a formula's reference value), and
/// `extra` at its end.
std::string baseline_case(const std::string& extra = "") {
  return std::string(test::kMinimalCase) +
         "\n[[observe]]\nkind = \"final_speed\"\nbody = \"ball\"\n"
         "\n[[observe]]\nkind = \"terminal_velocity\"\nbody = \"ball\"\n" +
         extra;
}

/// A folder holding `case` run with two course backends: the baseline.
struct Baseline {
  std::string dir, case_file, out;
  Baseline(const std::string& name, const std::string& text = baseline_case())
      : dir(test::fresh_dir(name)),
        case_file(test::write_case(dir, "minimal.toml", text)),
        out(dir + "/kept") {
    const Outcome run = beachball("run " + case_file + " --out " + out + " --no-cost --backends " +
                                  std::string(kBackends));
    EXPECT_EQ(run.exit_code, 0) << run.out;
  }
  std::string json_file() const { return out + "/minimal.json"; }
  nlohmann::json json() const { return nlohmann::json::parse(std::ifstream(json_file())); }
  void write(const nlohmann::json& j) const { std::ofstream(json_file()) << j.dump(2); }
  Outcome check(const std::string& more = "") const {
    return beachball("check " + case_file + " --baseline " + out + " " + more);
  }
};

/// Every error metric of every row multiplied by `factor`.
void scale_errors(nlohmann::json& j, double factor) {
  for (auto& run : j["runs"])
    if (run["errors"].is_object())
      for (auto& [name, value] : run["errors"].items())
        if (value.is_number()) value = value.get<double>() * factor;
}

TEST(CheckBaseline, TheSameRunIsUnchangedAndPasses) {
  const Baseline kept("baseline_same");
  const Outcome o = kept.check();
  EXPECT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find("unchanged from the baseline"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find(" 0 worse, 0 better, "), std::string::npos) << o.out;
  // It ran what the baseline has, every backend at every dt: no row on one side only.
  EXPECT_EQ(o.out.find("not in the baseline"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("not run now"), std::string::npos) << o.out;
  // Every error metric of the two backends at both dts, and the observables beside.
  const std::size_t at = o.out.find("baseline " + kept.out + ": ");
  ASSERT_NE(at, std::string::npos) << o.out;
  const int compared = std::stoi(o.out.substr(at + kept.out.size() + 11));
  EXPECT_GE(compared, 2 * 2 * 5) << o.out;
  // Two shards compare, between them, each value once.
  int in_shards = 0;
  for (const char* shard : {"1/2", "2/2"}) {
    const Outcome part = kept.check(std::string("--shard ") + shard);
    EXPECT_EQ(part.exit_code, 0) << part.out;
    const std::size_t from = part.out.find("baseline " + kept.out + ": ");
    ASSERT_NE(from, std::string::npos) << part.out;
    in_shards += std::stoi(part.out.substr(from + kept.out.size() + 11));
  }
  EXPECT_EQ(in_shards, compared);
}

TEST(CheckBaseline, ABaselineTwiceAsGoodFailsNamingBothValuesAndTheRatio) {
  const Baseline kept("baseline_worse");
  nlohmann::json j = kept.json();
  // The explicit Euler row at report_dt, its position_max halved in the baseline.
  nlohmann::json* row = nullptr;
  for (auto& run : j["runs"])
    if (run["backend"] == "course/explicit-euler" && run["dt"] == j["report_dt"]) row = &run;
  ASSERT_NE(row, nullptr);
  const double now = (*row)["errors"]["position_max"].get<double>();
  const double before = now / 2;
  (*row)["errors"]["position_max"] = before;
  kept.write(j);
  const std::string junit = kept.dir + "/check.xml";
  const Outcome o = kept.check("--junit " + junit);
  EXPECT_EQ(o.exit_code, 1) << o.out;
  const std::string said = "course/explicit-euler dt " + format_dt(j["report_dt"].get<double>()) +
                           " position_max: " + significant_digits(before, 6) + " -> " +
                           significant_digits(now, 6) + " (x" +
                           significant_digits(now / before, 4) + ")";
  EXPECT_NE(o.out.find("worse: minimal " + said), std::string::npos) << said << "\n" << o.out;
  EXPECT_NE(o.out.find(" 1 worse, 0 better, "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("worse than the baseline"), std::string::npos) << o.out;
  std::string escaped = said;
  escaped.replace(escaped.find("->"), 2, "-&gt;");
  const std::string xml = test::bytes(junit);
  EXPECT_NE(xml.find("name=\"baseline course/explicit-euler position_max\">\n      <failure "
                     "message=\"worse: " +
                     escaped + "\"/>"),
            std::string::npos)
      << escaped << "\n"
      << xml;
  // The case's tolerance decides: 1.5 lets a value grow to 2.5 times the baseline's.
  const std::string tolerant =
      test::write_case(kept.dir, "tolerant.toml", baseline_case("\n[baseline]\ntolerance = 1.5\n"));
  const Outcome passed = beachball("check " + tolerant + " --baseline " + kept.out);
  EXPECT_EQ(passed.exit_code, 0) << passed.out;
  EXPECT_NE(passed.out.find("unchanged from the baseline"), std::string::npos) << passed.out;
  const std::string strict =
      test::write_case(kept.dir, "strict.toml", baseline_case("\n[baseline]\ntolerance = 0.5\n"));
  EXPECT_EQ(beachball("check " + strict + " --baseline " + kept.out).exit_code, 1);
}

TEST(CheckBaseline, ABaselineMadeWorsePassesAndSaysBetter) {
  const Baseline kept("baseline_better");
  nlohmann::json j = kept.json();
  scale_errors(j, 2.0);
  kept.write(j);
  const Outcome o = kept.check();
  EXPECT_EQ(o.exit_code, 0) << o.out;
  EXPECT_NE(o.out.find("better: minimal course/rk4 dt "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find(" 0 worse, "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("better than the baseline where it changed, nothing worse"),
            std::string::npos)
      << o.out;
}

TEST(CheckBaseline, ABaselineThatIsNotResultsIsBadInputAndNothingIsWritten) {
  const Baseline kept("baseline_bad");
  const std::string junit = kept.dir + "/check.xml";
  std::string text = test::bytes(kept.json_file());
  std::ofstream(kept.json_file()) << text.substr(0, text.size() / 2);
  const Outcome cut = kept.check("--junit " + junit);
  EXPECT_EQ(cut.exit_code, 2) << cut.out;
  EXPECT_NE(cut.out.find(kept.json_file() + ":"), std::string::npos) << cut.out;
  EXPECT_NE(cut.out.find("is not JSON"), std::string::npos) << cut.out;
  EXPECT_FALSE(fs::exists(junit));
  const Outcome missing = beachball("check " + kept.case_file + " --baseline " + kept.dir +
                                    "/nowhere --junit " + junit);
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
  EXPECT_NE(missing.out.find(kept.dir + "/nowhere: no such folder"), std::string::npos)
      << missing.out;
  EXPECT_FALSE(fs::exists(junit));
  const Outcome empty = beachball("check " + kept.case_file + " --baseline ''");
  EXPECT_EQ(empty.exit_code, 2) << empty.out;
  EXPECT_NE(empty.out.find("--baseline: is empty"), std::string::npos) << empty.out;
  // A case with no results in the folder is said, and not a failure.
  fs::remove(kept.json_file());
  const Outcome none = kept.check();
  EXPECT_EQ(none.exit_code, 0) << none.out;
  EXPECT_NE(none.out.find("no baseline for case minimal"), std::string::npos) << none.out;
}

}  // namespace
}  // namespace bb
