// A run against its baseline: a value larger by more than the tolerance is worse, smaller
// is better, within it unchanged; a value near zero moves by less than the floor without a
// verdict; a status that left ok is worse; a row or value on one side only is named.
#include "run/baseline.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace bb {
namespace {

RunRecord row(const std::string& backend, double dt, double position_max) {
  RunRecord r;
  r.backend = backend;
  r.dt = dt;
  ErrorMetrics e;
  e.position_max = position_max;
  e.position_rms = position_max / 2;
  e.position_final = position_max / 3;
  e.velocity_max = position_max * 4;
  e.energy_max = 0.0;
  r.errors = e;
  ObservableResult o;
  o.name = "final_speed/ball";
  o.measured.value = 10.0 + position_max;
  o.reference = 10.0;
  r.observables.push_back(o);
  return r;
}

std::vector<BaselineComparison> compare(const RunRecord& before, const RunRecord& now,
                                        BaselineOptions options = {}) {
  return compare_with_baseline({&before}, {&now}, options);
}

/// The comparison of `metric` (a copy: `all` is often a temporary).
BaselineComparison find(const std::vector<BaselineComparison>& all, const std::string& metric) {
  const auto it = std::find_if(all.begin(), all.end(),
                               [&](const BaselineComparison& c) { return c.metric == metric; });
  EXPECT_NE(it, all.end()) << metric;
  return it == all.end() ? BaselineComparison{} : *it;
}

TEST(Baseline, TheSameRunIsUnchangedInEveryValue) {
  const RunRecord r = row("course/rk4", 0.01, 1e-3);
  const auto all = compare(r, r);
  // Five error metrics and the observable with a reference value.
  ASSERT_EQ(all.size(), 6u);
  for (const BaselineComparison& c : all) {
    EXPECT_EQ(c.change, Change::Unchanged) << c.metric;
    EXPECT_EQ(change_ratio(c), 1.0) << c.metric;
  }
}

TEST(Baseline, TwiceTheErrorIsWorseWithItsRatioHalfIsBetter) {
  const RunRecord before = row("course/rk4", 0.01, 1e-3), now = row("course/rk4", 0.01, 2e-3);
  const BaselineComparison worse = find(compare(before, now), "position_max");
  EXPECT_EQ(worse.change, Change::Worse);
  EXPECT_EQ(*worse.before, 1e-3);
  EXPECT_EQ(*worse.now, 2e-3);
  EXPECT_DOUBLE_EQ(change_ratio(worse), 2.0);
  // The observable's distance from its reference value doubled too.
  EXPECT_EQ(find(compare(before, now), "final_speed/ball").change, Change::Worse);
  EXPECT_EQ(find(compare(now, before), "position_max").change, Change::Better);
  // energy_max is 0 on both sides: unchanged, not a division by zero.
  EXPECT_EQ(find(compare(before, now), "energy_max").change, Change::Unchanged);
}

TEST(Baseline, TheToleranceAndTheFloorDecide) {
  const RunRecord before = row("ode", 0.01, 1e-3), now = row("ode", 0.01, 1e-3 * (1 + 5e-4));
  // Half the default tolerance: unchanged; a tolerance ten times tighter: worse.
  EXPECT_EQ(find(compare(before, now), "position_max").change, Change::Unchanged);
  EXPECT_EQ(find(compare(before, now, {1e-4, 0.0}), "position_max").change, Change::Worse);
  // Three times a value at rounding's size is within the default floor.
  const RunRecord tiny = row("ode", 0.01, 1e-16), triple = row("ode", 0.01, 3e-16);
  EXPECT_EQ(find(compare(tiny, triple), "position_max").change, Change::Unchanged);
  EXPECT_EQ(find(compare(tiny, triple, {1e-3, 0.0}), "position_max").change, Change::Worse);
}

TEST(Baseline, AStatusThatLeftOkIsWorseAndOneThatReachedItBetter) {
  const RunRecord ok = row("course/explicit-euler", 0.1, 1.0);
  RunRecord diverged = ok;
  diverged.status = RunStatus::Diverged;
  diverged.reason = "energy grew";
  const auto lost = compare(ok, diverged);
  ASSERT_EQ(lost.size(), 1u);
  EXPECT_EQ(lost[0].metric, "status");
  EXPECT_EQ(lost[0].change, Change::Worse);
  EXPECT_NE(lost[0].note.find("ok -> diverged: energy grew"), std::string::npos) << lost[0].note;
  EXPECT_EQ(compare(diverged, ok)[0].change, Change::Better);
  EXPECT_EQ(compare(diverged, diverged)[0].change, Change::NothingToCompare);
}

TEST(Baseline, ARowOrAValueOnOneSideIsNamedNotJudged) {
  const RunRecord a = row("bullet", 0.01, 1e-3), b = row("bullet", 0.005, 1e-3);
  const auto all = compare_with_baseline({&a}, {&b}, {});
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].note, "not in the baseline");
  EXPECT_EQ(all[1].note, "in the baseline, not run now");
  for (const BaselineComparison& c : all) EXPECT_EQ(c.change, Change::NotCompared);
  // An observable measured now and not in the baseline (no reference value there).
  RunRecord no_reference = a;
  no_reference.observables[0].reference.reset();
  const BaselineComparison c = find(compare(no_reference, a), "final_speed/ball");
  EXPECT_EQ(c.change, Change::NotCompared);
  EXPECT_EQ(c.note, "no value in the baseline");
  EXPECT_EQ(find(compare(no_reference, no_reference), "final_speed/ball").change,
            Change::NothingToCompare);
}

}  // namespace
}  // namespace bb
