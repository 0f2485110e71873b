// The sweep on a case page: per backend which way a result goes as the parameter grows, its
// range and its largest step between neighbouring values, computed from the points; where
// it starts; and every value when there are few, a missing value saying why.
#include "report/sweep_page.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "report/gnuplot.hpp"
#include "support/missing.hpp"
#include "support/picture_support.hpp"
#include "support/program.hpp"
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
  SweepResults sweep{"air.density", {}, ""};
  const double smooth[] = {1.0, 2.0, 3.0};
  const double bumpy[] = {1.0, 4.0, 2.0};
  for (int k = 0; k < 3; ++k)
    sweep.points.push_back({1.0 + k,
                            0.0,
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

/// The numbers gnuplot writes as tic labels of `panel`: along its bottom, or left of it.
std::vector<double> tics(const std::string& svg, const test::Box& panel, bool bottom) {
  std::vector<double> out;
  for (const test::SvgText& t : test::svg_texts(svg)) {
    if (t.turned || t.text.empty() ||
        t.text.find_first_not_of(" -.0123456789e+") != std::string::npos)
      continue;
    const bool below = t.anchor == "middle" && t.y > panel.y1 && t.y < panel.y1 + 25 &&
                       t.x > panel.x0 - 5 && t.x < panel.x1 + 5;
    const bool left = t.anchor == "end" && t.x < panel.x0 && t.x > panel.x0 - 80 &&
                      t.y > panel.y0 - 5 && t.y < panel.y1 + 10;
    if (bottom ? below : left) out.push_back(std::stod(t.text));
  }
  return out;
}

// The sweep's plot: every panel spans the whole sweep (the difference panel, with no point
// where the reference has no answer, started at the third value beside a value panel that
// started at the first), and one backend far off the reference's scale (490 beside values
// of 1 to 5) is cut at the panel's edge and named, so the others' curves stay readable.
TEST(SweepPlot, PanelsSpanTheWholeSweepAndAnOutlierIsCutAndNamed) {
  BB_SKIP_IF_MISSING(
      gnuplot_available() ? "" : "gnuplot is not installed (scripts/setup installs gnuplot-nox)");
  static Scene scene;
  scene = test::scene_from(test::minimal_case("swept") + R"(
[[observe]]
kind = "final_speed"
body = "ball"
[[sweep]]
parameter = "air.density"
values = [1.0, 2.0, 3.0, 4.0, 5.0]
)");
  CaseResults results;
  results.scene = &scene;
  SweepResults sweep{"air.density", {}, ""};
  for (int k = 0; k < 5; ++k) {
    const double v = 1.0 + k;
    // The reference has no answer at the first two values.
    const std::optional<double> reference = k < 2 ? std::nullopt : std::optional(v);
    sweep.points.push_back({v,
                            0.0,
                            {row("reference", reference, ""), row("course/rk4", v + 0.1, ""),
                             row("bullet", k == 3 ? 490.0 : v - 0.1, "")}});
  }
  results.sweep = sweep;
  const std::string dir = test::fresh_dir("sweep_outlier");
  std::filesystem::create_directories(dir);
  {
    FileBatch batch(dir);
    ASSERT_EQ(sweep_plot(results, batch, "s.svg"), "");
    batch.commit();
  }
  const std::string svg = test::bytes(dir + "/s.svg");
  const test::GnuplotLayout layout = test::gnuplot_layout(svg);
  ASSERT_GE(layout.panels.size(), 2u);
  // The first row's two panels: the values left, the differences right.
  std::vector<test::Box> row = layout.panels;
  std::sort(row.begin(), row.end(),
            [](const auto& a, const auto& b) { return a.y0 != b.y0 ? a.y0 < b.y0 : a.x0 < b.x0; });
  const test::Box values = row[0], differences = row[1];
  ASSERT_NEAR(values.y0, differences.y0, 1.0);
  for (const test::Box& panel : {values, differences}) {
    const std::vector<double> x = tics(svg, panel, true);
    ASSERT_FALSE(x.empty());
    EXPECT_NEAR(*std::min_element(x.begin(), x.end()), 1.0, 1e-9) << "starts off the sweep";
    EXPECT_NEAR(*std::max_element(x.begin(), x.end()), 5.0, 1e-9) << "ends off the sweep";
  }
  // The value panel is on the others' scale: no tic near 490; the cut backend is named.
  const std::vector<double> y = tics(svg, values, false);
  ASSERT_FALSE(y.empty());
  EXPECT_LT(*std::max_element(y.begin(), y.end()), 50.0);
  EXPECT_NE(svg.find("bullet (reaches 490)"), std::string::npos);
  EXPECT_EQ(svg.find("course/rk4 (reaches"), std::string::npos);
}

}  // namespace
}  // namespace bb
