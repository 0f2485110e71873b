// A report writes each case's pages as soon as the case has run and then drops the series only
// those pages read (drop_page_series): the index and the claims ledger, written after every
// case, must read nothing the drop takes away, on a case with claims and on a map with a claim
// over its region.
#include <gtest/gtest.h>

#include "report/claims_page.hpp"
#include "report/index_page.hpp"
#include "run/case_runner.hpp"
#include "support/claims_support.hpp"
#include "support/spring_map_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A 2 x 2 spring map with a claim on semi-implicit Euler inside the theory's region.
std::string claimed_map() {
  return test::spring_map_case("mapped", "[2.0, 800.0]", "[0.1, 0.01]",
                               R"(["semi-implicit-euler"])") +
         R"([[claim]]
text = "Semi-implicit Euler is ok below the line and explodes above it"
own = true
region = "theory"
backend = "course/semi-implicit-euler"
)";
}

/// States, energies and distances held by every run of `all`, sweep points included.
std::size_t series_held(const std::vector<CaseResults>& all) {
  std::size_t n = 0;
  const auto count = [&n](const RunRecord& run) {
    n += run.trajectory.states.size() + run.trajectory.times.size() + run.energy.size() +
         run.distance.size();
  };
  for (const CaseResults& r : all) {
    count(r.reference_run);
    for (const RunRecord& run : r.runs) count(run);
    if (r.sweep)
      for (const SweepPoint& p : r.sweep->points)
        for (const RunRecord& run : p.runs) count(run);
  }
  return n;
}

TEST(PageSeries, TheIndexAndTheLedgerReadNothingTheDropTakes) {
  const Scene fall = test::scene_from(test::fall_case() + R"([[claim]]
text = "the ball falls slower than it would in a vacuum"
own = true
left = "reference:final_speed/ball"
op = "<"
right = 19.62
[[claim]]
text = "the error is small"
own = true
left = "*:position_max"
op = "<"
right = 0.5
)");
  const Scene map = test::scene_from(claimed_map());
  RunOptions options;
  options.backends = {"course/explicit-euler", "course/semi-implicit-euler"};
  options.cost = false;
  options.jobs = 2;
  std::vector<CaseResults> all;
  all.push_back(run_case(fall, Registry::load(), options));
  options.backends = {"course/semi-implicit-euler"};
  all.push_back(run_case(map, Registry::load(), options));
  ASSERT_TRUE(all[1].sweep);
  ASSERT_FALSE(all[0].claims.empty() || all[1].claims.empty());
  const std::vector<std::string> plots(all.size());
  const IndexSource source{"two cases", "a test"};
  const std::string index = index_page(all, plots, false, 2, source);
  const std::string ledger = claims_page(all);
  ASSERT_GT(series_held(all), 0u) << "nothing to drop: the test would prove nothing";

  for (CaseResults& r : all) drop_page_series(r);

  EXPECT_EQ(series_held(all), 0u);
  EXPECT_EQ(index_page(all, plots, false, 2, source), index);
  EXPECT_EQ(claims_page(all), ledger);
}

}  // namespace
}  // namespace bb
