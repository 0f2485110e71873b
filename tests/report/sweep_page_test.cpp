// The sweep on a case page: per backend which way a result goes as the parameter grows, its
// range and its largest step between neighbouring values, computed from the points; where
// it starts; and every value when there are few, a missing value saying why.
#include "report/sweep_page.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace bb {
namespace {

RunRecord row(const std::string& backend, std::optional<double> speed, const std::string& note) {
  RunRecord r;
  r.backend = backend;
  ObservableResult o;
  o.name = "final_speed/ball";
  o.measured = {speed, note};
  r.observables.push_back(o);
  return r;
}

TEST(SweepPage, TrendRangeLargestStepOnsetAndEveryValueComeFromThePoints) {
  static Scene scene;
  scene = test::scene_from(test::minimal_case("swept") + R"(
[[observe]]
kind = "final_speed"
body = "ball"
[[sweep]]
parameter = "air.density"
values = [1.0, 2.0, 3.0]
onset = "final_speed/ball"
onset_above = 2.5
)");
  CaseResults results;
  results.scene = &scene;
  SweepResults sweep{"air.density", {}};
  const double smooth[] = {1.0, 2.0, 3.0};
  const double bumpy[] = {1.0, 4.0, 2.0};
  for (int k = 0; k < 3; ++k)
    sweep.points.push_back({1.0 + k,
                            {row("reference", smooth[k], ""), row("bumpy", bumpy[k], ""),
                             row("silent", std::nullopt, "it never got going")}});
  results.sweep = sweep;
  const std::string page = sweep_markdown(results, "");
  // Trend, range and largest step per backend, in the predictability table.
  const std::size_t table = page.find("### Predictability");
  ASSERT_NE(table, std::string::npos);
  const auto line_of = [&](const std::string& backend, std::size_t from) {
    const std::size_t at = page.find("| " + backend + " ", from);
    return at == std::string::npos ? std::string() : page.substr(at, page.find('\n', at) - at);
  };
  const std::string reference = line_of("reference", table), bumpy_row = line_of("bumpy", table);
  EXPECT_NE(reference.find("| rises "), std::string::npos) << reference;
  EXPECT_NE(reference.find(" 1 to 3 |"), std::string::npos) << reference;
  EXPECT_NE(bumpy_row.find("| up and down "), std::string::npos) << bumpy_row;
  EXPECT_NE(bumpy_row.find(" 1 to 4 |"), std::string::npos) << bumpy_row;
  EXPECT_NE(bumpy_row.find(" 3 |"), std::string::npos) << "largest step 4 - 1: " << bumpy_row;
  // Onset: the reference passes 2.5 at the third value, bumpy at the second, silent never.
  const std::size_t onset = page.find("### Where it starts");
  ASSERT_NE(onset, std::string::npos);
  EXPECT_NE(line_of("reference", onset).find(" 3 |"), std::string::npos);
  EXPECT_NE(line_of("bumpy", onset).find(" 2 |"), std::string::npos);
  EXPECT_NE(line_of("silent", onset).find("never in the sweep"), std::string::npos);
  // Every value: the missing one says why.
  EXPECT_NE(page.find("it never got going"), std::string::npos);
}

}  // namespace
}  // namespace bb
