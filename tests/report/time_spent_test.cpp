// The index page's "where the time went": the whole report's row sums every case's parts,
// the cases follow slowest first, runs taken from kept results are not counted as runs,
// and a report with nothing timed has no section.
#include "report/time_spent.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <sstream>

namespace bb {
namespace {

/// The cells of the table row whose first cell is `name`, trimmed; empty when none is.
std::vector<std::string> cells(const std::string& page, const std::string& name) {
  std::istringstream lines(page);
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> out;
    std::istringstream parts(line);
    for (std::string cell; std::getline(parts, cell, '|');) {
      const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
      if (first != std::string::npos) out.push_back(cell.substr(first, last - first + 1));
    }
    if (!out.empty() && out[0] == name) return out;
  }
  return {};
}

TEST(TimeSpent, SumsThePartsAndPutsTheSlowestCaseFirst) {
  Scene quick, slow;
  quick.name = "quick";
  slow.name = "slow";
  std::vector<CaseResults> all(2);
  all[0].scene = &quick;
  all[0].time_spent = {1.0, 0.5, 0.25, 0.0};
  all[1].scene = &slow;
  all[1].time_spent = {10.0, 2.0, 3.0, 4.0};
  const std::string page = time_spent_section(all, 2);
  EXPECT_EQ(cells(page, "all cases"),
            (std::vector<std::string>{"all cases", "11.0", "2.5", "3.2", "4.0", "20.8"}))
      << page;
  EXPECT_EQ(cells(page, "slow"),
            (std::vector<std::string>{"slow", "10.0", "2.0", "3.0", "4.0", "19.0"}));
  EXPECT_LT(page.find("| slow "), page.find("| quick "));
}

// The floor: the accuracy runs' steps alone, on the jobs that ran them: from their costs, or
// their own timed steps where they have none (a run that diverged, the reference), and the
// reference's second solve (its self-check) too.
TEST(TimeSpent, SaysWhatTheStepsAloneTakeAndTheCostOfARun) {
  Scene scene;
  scene.name = "timed";
  std::vector<CaseResults> all(1);
  all[0].scene = &scene;
  all[0].time_spent = {6.0, 1.0, 0.0, 0.0};
  all[0].reference_run.steps = 1000;
  all[0].reference_run.cost = Cost{1e6, 0.0, 3, 1e6, 1e6, ""};  // 1 ms a step: 1 s
  all[0].runs.resize(2);
  all[0].runs[0].steps = 2000;
  all[0].runs[0].cost = Cost{1.5e6, 0.0, 3, 1e6, 2e6, ""};  // 3 s
  all[0].runs[1].steps = 10;                                // no cost: its own timed steps
  all[0].runs[1].step_seconds = 0.25;
  all[0].time_spent.self_check_steps = 0.75;
  const std::string page = time_spent_section(all, 2);
  EXPECT_NE(page.find("The accuracy runs: 3 ran (the references and every backend at every dt), "
                      "6.0 s on 2 jobs, so 4.000 s of a core per run"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("take 5.0 s of one core"), std::string::npos) << page;
  EXPECT_NE(page.find("no less than 2.5 s with --jobs 2"), std::string::npos) << page;
}

// The runs with a cost timed two ways: their costs (step() alone, in a loop of its own) and
// their own blocks of steps (with what observes each step); the page gives both and their ratio.
TEST(TimeSpent, SetsTheRunsOwnTimingBesideTheirCosts) {
  Scene scene;
  scene.name = "timed";
  std::vector<CaseResults> all(1);
  all[0].scene = &scene;
  all[0].time_spent = {6.0, 1.0, 0.0, 0.0};
  all[0].runs.resize(3);
  all[0].runs[0].steps = 2000;
  all[0].runs[0].cost = Cost{1.5e6, 0.0, 3, 1e6, 2e6, ""};  // 3 s from its cost
  all[0].runs[0].step_seconds = 4.5;                        // 4.5 s timed in the run
  all[0].runs[1].steps = 1000;
  all[0].runs[1].cost = Cost{1e6, 0.0, 3, 1e6, 1e6, ""};  // 1 s from its cost
  all[0].runs[1].step_seconds = 1.5;
  all[0].runs[2].steps = 10;  // no cost: counted in neither
  all[0].runs[2].step_seconds = 7.0;
  const std::string page = time_spent_section(all, 2);
  EXPECT_NE(page.find("the runs with a cost stepped for 6.0 s of one core, 1.50 times the 4.0 s "
                      "their costs give"),
            std::string::npos)
      << page;
}

// A run taken from kept results took no run's time: the per-run figure and the floor count
// only the runs that ran, and the page says how many were reused.
TEST(TimeSpent, RunsTakenFromKeptResultsAreNotCountedAsRuns) {
  Scene scene;
  scene.name = "kept";
  std::vector<CaseResults> all(1);
  all[0].scene = &scene;
  all[0].time_spent = {6.0, 1.0, 0.0, 0.0};
  all[0].reference_run.steps = 1000;
  all[0].reference_run.cost = Cost{1e6, 0.0, 3, 1e6, 1e6, ""};  // 1 s, run
  all[0].runs.resize(3);
  for (RunRecord& run : all[0].runs) {
    run.steps = 2000;
    run.cost = Cost{1.5e6, 0.0, 3, 1e6, 2e6, ""};  // 3 s each
    run.reused = true;
  }
  all[0].runs[0].reused = false;
  const std::string page = time_spent_section(all, 2);
  EXPECT_NE(page.find("The accuracy runs: 2 ran"), std::string::npos) << page;
  EXPECT_NE(page.find("so 6.000 s of a core per run"), std::string::npos) << page;
  EXPECT_NE(page.find("2 more were taken from kept results"), std::string::npos) << page;
  EXPECT_NE(page.find("take 4.0 s of one core"), std::string::npos) << page;
  // All of them reused: no figure per run.
  all[0].reference_run.reused = true;
  all[0].runs[0].reused = true;
  const std::string none = time_spent_section(all, 2);
  EXPECT_NE(none.find("none ran"), std::string::npos) << none;
  EXPECT_EQ(none.find("per run"), std::string::npos) << none;
}

// The whole report against its floor: the parts' wall time over the steps' seconds of a core
// (the accuracy runs' from their costs, the cost pass's timed steps, the stability trials'
// and the sweep runs' step loops) divided by the jobs, all from the run's own figures.
TEST(TimeSpent, PrintsTheWholeReportsRatioToItsFloor) {
  Scene scene;
  scene.name = "floored";
  std::vector<CaseResults> all(1);
  CaseResults& r = all[0];
  r.scene = &scene;
  r.time_spent = {6.0, 1.5, 2.0, 0.5};  // 10 s of wall
  r.time_spent.cost_steps = 1.0;
  r.reference_run.steps = 1000;
  r.reference_run.cost = Cost{1e6, 0.0, 3, 1e6, 1e6, ""};  // 1 s of steps
  r.runs.resize(1);
  r.runs[0].steps = 2000;
  r.runs[0].cost = Cost{1.5e6, 0.0, 3, 1e6, 2e6, ""};  // 3 s
  r.stability.resize(2);
  r.stability[0].step_seconds = 0.75;
  r.stability[1].step_seconds = 0.25;
  r.sweep = SweepResults{"drop height", {}, ""};
  r.sweep->points.resize(2);
  r.sweep->points[0].runs.resize(1);
  r.sweep->points[0].runs[0].step_seconds = 0.5;
  r.sweep->points[1].runs.resize(1);
  r.sweep->points[1].runs[0].step_seconds = 0.5;
  // Steps: 4 + 1 + 1 + 1 = 7 s of a core, 3.5 s on 2 jobs; 10 s of wall: 2.86 times.
  const std::string page = time_spent_section(all, 2);
  EXPECT_NE(
      page.find(
          "its steps alone took 7.0 s of one core (accuracy runs, from their costs or "
          "their timed steps 4.0 s, the cost pass's timed steps 1.0 s, the stability trials' step "
          "loops 1.0 s, the sweep runs' steps 1.0 s), so 3.5 s on 2 jobs"),
      std::string::npos)
      << page;
  EXPECT_NE(page.find("Its runs took 10.0 s"), std::string::npos) << page;
  EXPECT_NE(page.find(fmt::format("**{:.2f} times its floor**", 10.0 / 3.5)), std::string::npos)
      << page;
  // Nothing stepped: no ratio to print.
  all[0] = CaseResults{};
  all[0].scene = &scene;
  all[0].time_spent = {6.0, 1.5, 2.0, 0.5};
  EXPECT_EQ(time_spent_section(all, 2).find("times its floor"), std::string::npos);
}

TEST(TimeSpent, NothingTimedIsNoSection) {
  Scene scene;
  scene.name = "untimed";
  std::vector<CaseResults> all(1);
  all[0].scene = &scene;
  EXPECT_EQ(time_spent_section(all, 2), "");
}

}  // namespace
}  // namespace bb
