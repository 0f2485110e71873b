// The plots as a reader sees them, on a projector: rendered by rsvg-convert, nothing is
// drawn at the picture's edge (a label or legend cut off); read from the SVG, each panel's
// name stays within its column and no legend entry sits over a panel's data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support/missing.hpp"
#include "support/picture_support.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

/// Runs the bundled case `name` without the timing pass into `dir`/`name`, at its report_dt
/// only where `report_dt_only` (the plots at report_dt are the same; the work-precision
/// plots then have one point per backend).
void run_bundled(const std::string& dir, const std::string& name, const std::string& dt = "") {
  const test::Outcome o =
      test::beachball("run " + test::source_path("cases/" + name + ".toml") + " --no-cost" +
                      (dt.empty() ? "" : " --dt " + dt) + " --out " + dir + "/" + name);
  ASSERT_EQ(o.exit_code, 0) << o.out;
}

std::string text_of(const fs::path& path) {
  return test::bytes(path.string());
}

TEST(PlotEdges, NoPlotDrawsAtTheEdgeOfItsPicture) {
  BB_SKIP_IF_MISSING(test::why_no_pictures());
  const std::string dir = test::fresh_dir("plot_edges");
  // Long backend names (the friction variants) and two-column plots: the cases whose labels
  // were cut at the picture's edge; the energy plot of a case whose many exploding runs
  // are named above it (cloth_stiff's line ran off the left edge), and the sweep's panels
  // (wind_panel's long names on the side of its panels touched the left and top edges).
  // Their three coarsest steps (the report's 1/60 among them): the plots and their labels are
  // all there, the finer steps' runs (most of the time) add nothing drawn at an edge.
  for (const char* name : {"sliding_block", "drag_fall"}) run_bundled(dir, name, "1/30,1/60,1/120");
  run_bundled(dir, "cloth_stiff", "1/60");
  run_bundled(dir, "wind_panel", "1/60");
  int pictures = 0;
  std::vector<std::string> kinds;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".svg") continue;
    const std::string png = entry.path().string() + ".png";
    ASSERT_EQ(std::system(("rsvg-convert " + entry.path().string() + " -o " + png).c_str()), 0);
    const test::Image image = test::read_png(png);
    ASSERT_GT(image.width, 4) << entry.path();
    ++pictures;
    kinds.push_back(entry.path().filename().string());
    // Nothing but background within two pixels of any edge: a label, a title or a legend
    // that runs off the picture leaves dark pixels there.
    const auto inked = [&](int x, int y) {
      const unsigned char* p = image.at(x, y);
      return p[3] > 0 && (p[0] < 200 || p[1] < 200 || p[2] < 200);
    };
    int sides = 0, ends = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x : {0, 1, image.width - 2, image.width - 1}) sides += inked(x, y);
    for (int x = 0; x < image.width; ++x)
      for (int y : {0, 1, image.height - 2, image.height - 1}) ends += inked(x, y);
    EXPECT_EQ(sides, 0) << entry.path() << " is drawn up to its left or right edge";
    EXPECT_EQ(ends, 0) << entry.path() << " is drawn up to its top or bottom edge";
  }
  EXPECT_GE(pictures, 20);
  for (const char* kind : {"cloth_stiff-energy.svg", "wind_panel-sweep.svg"})
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), kind), kinds.end()) << kind;
}

// The names of the sweep's panels stay in their own column: each panel's name is above it
// and no wider than it, and no text is turned on its side (wind_panel's right column named
// its panels by y labels longer than the panels, over the left column's panels).
TEST(PlotEdges, TheSweepsPanelsAreNamedWithinTheirColumn) {
  const std::string dir = test::fresh_dir("sweep_names");
  run_bundled(dir, "wind_panel", "1/60");
  const std::string svg = text_of(dir + "/wind_panel/wind_panel-sweep.svg");
  ASSERT_FALSE(svg.empty());
  const test::GnuplotLayout layout = test::gnuplot_layout(svg);
  ASSERT_GE(layout.panels.size(), 4u);
  int named = 0;
  for (const test::SvgText& t : test::svg_texts(svg)) {
    EXPECT_FALSE(t.turned) << t.text << " is turned on its side";
    // A line centred over a panel, above it: the panel's name.
    for (const test::Box& p : layout.panels)
      if (t.anchor == "middle" && std::abs(t.x - (p.x0 + p.x1) / 2) < 1.0 && t.y < p.y0 &&
          t.y > p.y0 - 60) {
        ++named;
        EXPECT_LE(test::text_width(t.text, t.size), p.x1 - p.x0) << t.text;
      }
  }
  EXPECT_GE(named, static_cast<int>(layout.panels.size()));
}

// The legend has a band of its own: for a case with many backends (ball_in_box: twelve
// course variants and every engine) no entry of any plot's legend lies over a panel's
// plotting area. Its trajectory's two-column legend sat over the first panel's data.
TEST(PlotLegend, NoLegendEntryLiesOverAPanel) {
  const std::string dir = test::fresh_dir("plot_legend");
  run_bundled(dir, "ball_in_box", "1/60");
  run_bundled(dir, "wind_panel", "1/60");
  int plots = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".svg" ||
        entry.path().filename().string().find("motion") != std::string::npos)
      continue;
    const test::GnuplotLayout layout = test::gnuplot_layout(text_of(entry.path()));
    ASSERT_FALSE(layout.panels.empty()) << entry.path();
    ASSERT_FALSE(layout.legend.empty()) << entry.path();
    ++plots;
    for (const auto& e : layout.legend)
      for (const test::Box& p : layout.panels)
        EXPECT_FALSE(e.box.overlaps(p))
            << entry.path().filename() << ": the legend's " << e.title << " at [" << e.box.x0
            << ", " << e.box.x1 << "] x [" << e.box.y0 << ", " << e.box.y1
            << "] lies over the panel [" << p.x0 << ", " << p.x1 << "] x [" << p.y0 << ", " << p.y1
            << "]";
  }
  EXPECT_GE(plots, 5);
  const std::string trajectory = text_of(dir + "/ball_in_box/ball_in_box-trajectory.svg");
  EXPECT_GE(test::gnuplot_layout(trajectory).legend.size(), 20u);
}

}  // namespace
}  // namespace bb
