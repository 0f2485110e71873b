// Long runs are thinned for drawing: every bucket keeps its lowest and highest point, so
// peaks survive, and a 20,000-sample run still draws pages under 1 MB of SVG.
#include "report/plots.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "files/file_batch.hpp"
#include "report/gnuplot.hpp"
#include "support/missing.hpp"
#include "support/picture_support.hpp"
#include "support/program.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

TEST(Thinned, ShortSeriesAreDrawnWhole) {
  const std::vector<double> values(kMaxPlotPoints, 1.0);
  EXPECT_EQ(thinned(values, kMaxPlotPoints).size(), values.size());
}

TEST(Thinned, LongSeriesKeepTheirEndsPeaksAndOrder) {
  // A noisy sine with one spike: the spike and both ends must survive.
  std::vector<double> values;
  for (int j = 0; j < 100000; ++j) values.push_back(std::sin(j * 1e-3) + 1e-3 * (j % 7));
  values[61234] = 50.0;
  const std::vector<std::size_t> keep = thinned(values, 2000);
  EXPECT_LE(keep.size(), 2000u);
  EXPECT_EQ(keep.front(), 0u);
  EXPECT_EQ(keep.back(), values.size() - 1);
  EXPECT_TRUE(std::is_sorted(keep.begin(), keep.end()));
  EXPECT_NE(std::find(keep.begin(), keep.end(), 61234u), keep.end());
  const auto lowest = std::min_element(values.begin(), values.end()) - values.begin();
  EXPECT_NE(std::find(keep.begin(), keep.end(), static_cast<std::size_t>(lowest)), keep.end());
}

TEST(Plots, ALongRunsPagesStayUnderOneMegabyte) {
  const std::string dir = test::fresh_dir("long_plots");
  const std::string path = test::write_case(dir, "long_fall.toml", R"(name = "long_fall"
dims = 2
duration = 2000.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05
[air]
density = 1.2
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 10.0, 0.0]
velocity = [3.0, 0.0, 0.0]
drag_coefficient = 0.47
)");
  const test::Outcome o = test::beachball("run " + path +
                                          " --no-cost --backends course/semi-implicit-euler,"
                                          "course/rk4 --out " +
                                          dir + "/out");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  int svgs = 0;
  for (const auto& entry : fs::directory_iterator(dir + "/out")) {
    if (entry.path().extension() != ".svg") continue;
    ++svgs;
    EXPECT_LT(fs::file_size(entry.path()), 1u << 20) << entry.path();
  }
  EXPECT_GE(svgs, 3);
}

// A case the reference cannot answer (two balls stacked at the start) still gets its page
// and its plots: runs without states draw nothing (gnuplot refused the empty series before),
// the distance plot is left out with the reason, and the page says what errors are against.
TEST(Plots, ACaseWithoutAReferenceStillGetsItsPageAndPlots) {
  const std::string dir = test::fresh_dir("no_reference_plots");
  const std::string path = test::write_case(dir, "stack.toml", test::kStackedBalls);
  const test::Outcome o = test::beachball(
      "run " + path + " --no-cost --backends course/semi-implicit-euler --out " + dir + "/out");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_TRUE(fs::exists(dir + "/out/stack-trajectory.svg"));
  EXPECT_TRUE(fs::exists(dir + "/out/stack-energy.svg"));
  EXPECT_FALSE(fs::exists(dir + "/out/stack-error.svg"));
  std::ifstream in(dir + "/out/stack.md");
  const std::string page(std::istreambuf_iterator<char>(in), {});
  EXPECT_NE(page.find("finest dt"), std::string::npos);
}

// The trajectory plot shows the bodies that move: never a fixed body or a grid's anchored
// row (the cloth drew six flat lines of its anchored particles); a motion in the plane that
// goes both ways is drawn as its path, y against x.
TEST(Plots, TheTrajectoryPanelsShowTheBodiesThatMove) {
  const std::string dir = test::fresh_dir("moving_panels");
  const std::string path = test::write_case(dir, "hang.toml", R"(name = "hang"
dims = 2
duration = 1.0
sample = 0.02
dt = [0.02, 0.01]
report_dt = 0.01
[[body]]
name = "wall"
shape = "box"
half_extents = [0.2, 1.0, 0.5]
position = [-3.0, 8.0, 0.0]
fixed = true
[[body]]
name = "thrown"
radius = 0.2
mass = 1.0
position = [-5.0, 5.0, 0.0]
velocity = [3.0, 4.0, 0.0]
[grid]
size = [3, 2]
spacing = 1.0
mass = 0.1
neighbours = 4
stiffness = 50.0
damping = 0.2
origin = [0.0, 10.0, 0.0]
anchored = "top-row"
)");
  const test::Outcome o = test::beachball(
      "run " + path + " --no-cost --backends reference,course/rk4 --out " + dir + "/out");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  std::ifstream in(dir + "/out/hang-trajectory.svg");
  const std::string svg(std::istreambuf_iterator<char>(in), {});
  ASSERT_FALSE(svg.empty());
  for (const char* still : {"wall ", "p0_0 ", "p1_0 ", "p2_0 "})
    EXPECT_EQ(svg.find(still), std::string::npos) << still << "has a panel";
  for (const char* moving : {"p0_1 y (m)", "p1_1 y (m)", "p2_1 y (m)"})
    EXPECT_NE(svg.find(moving), std::string::npos) << moving;
  // The thrown ball's path: its x against its y.
  EXPECT_NE(svg.find("thrown x (m)"), std::string::npos);
  EXPECT_NE(svg.find("thrown y (m)"), std::string::npos);
}

/// Two balls falling through air from rest, one heavy and one light, compared by a claim
/// when `claimed`; with `explode`, a stiff spring that explicit Euler blows up.
std::string falling_pair(bool claimed, bool explode) {
  std::string text = R"(name = "pair"
dims = 2
duration = 2.0
sample = 0.02
dt = [0.02, 0.01]
report_dt = 0.01
[air]
density = 1.2
[[body]]
name = "heavy"
radius = 0.5
mass = 50.0
position = [0.0, 100.0, 0.0]
drag_coefficient = 0.47
[[body]]
name = "light"
radius = 0.5
mass = 0.5
position = [3.0, 100.0, 0.0]
drag_coefficient = 0.47
[[observe]]
kind = "final_speed"
body = "heavy"
[[observe]]
kind = "final_speed"
body = "light"
)";
  if (claimed)
    text += R"([[claim]]
text = "the heavy ball falls faster"
own = true
left = "*:final_speed/heavy"
op = ">"
right = "*:final_speed/light"
)";
  if (explode)
    text += R"([[body]]
name = "bob"
radius = 0.1
mass = 0.1
position = [10.0, 0.0, 0.0]
velocity = [0.0, 1.0, 0.0]
[[body]]
name = "post"
radius = 0.1
mass = 1.0
position = [10.0, 1.0, 0.0]
fixed = true
[[spring]]
bodies = ["bob", "post"]
stiffness = 4000.0
rest_length = 1.0
)";
  return text;
}

std::string svg_of(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Plots, BodiesAClaimComparesShareOnePanelAndAirGetsASpeedPlot) {
  for (const bool claimed : {false, true}) {
    const std::string dir = test::fresh_dir(claimed ? "claimed_pair" : "unclaimed_pair");
    const std::string path = test::write_case(dir, "pair.toml", falling_pair(claimed, false));
    const test::Outcome o = test::beachball(
        "run " + path + " --no-cost --backends reference,course/rk4 --out " + dir + "/out");
    ASSERT_EQ(o.exit_code, 0) << o.out;
    const std::string trajectory = svg_of(dir + "/out/pair-trajectory.svg");
    const std::string speed = svg_of(dir + "/out/pair-speed.svg");
    ASSERT_FALSE(trajectory.empty());
    ASSERT_FALSE(speed.empty()) << "air drags both balls: the page has a speed plot";
    if (claimed) {
      // One panel for both, each ball named on its curve.
      EXPECT_NE(trajectory.find("heavy, light y (m)"), std::string::npos);
      EXPECT_NE(speed.find("heavy, light speed (m/s)"), std::string::npos);
      EXPECT_NE(speed.find(">heavy<"), std::string::npos);
      EXPECT_NE(speed.find(">light<"), std::string::npos);
    } else {
      EXPECT_NE(trajectory.find("heavy y (m)"), std::string::npos);
      EXPECT_NE(trajectory.find("light y (m)"), std::string::npos);
      EXPECT_EQ(trajectory.find("heavy, light"), std::string::npos);
    }
    EXPECT_NE(svg_of(dir + "/out/pair.md").find("![speed](pair-speed.svg)"), std::string::npos);
  }
}

TEST(Plots, ACaseWithoutAirHasNoSpeedPlot) {
  const std::string dir = test::fresh_dir("no_air");
  std::string text = falling_pair(false, false);
  text.replace(text.find("[air]\ndensity = 1.2\n"), 19, "");
  for (std::size_t at; (at = text.find("drag_coefficient = 0.47\n")) != std::string::npos;)
    text.erase(at, 24);
  const std::string path = test::write_case(dir, "pair.toml", text);
  const test::Outcome o = test::beachball(
      "run " + path + " --no-cost --backends reference,course/rk4 --out " + dir + "/out");
  ASSERT_EQ(o.exit_code, 0) << o.out;
  EXPECT_FALSE(fs::exists(dir + "/out/pair-speed.svg"));
}

TEST(Plots, AnExplodingRunIsCutAtTheEnergyAxisAndNamed) {
  for (const bool explode : {false, true}) {
    const std::string dir = test::fresh_dir(explode ? "energy_cut" : "energy_whole");
    const std::string path = test::write_case(dir, "pair.toml", falling_pair(false, explode));
    const test::Outcome o = test::beachball(
        "run " + path + " --no-cost --backends reference,course/explicit-euler,course/rk4 --out " +
        dir + "/out");
    ASSERT_EQ(o.exit_code, 0) << o.out;
    const std::string energy = svg_of(dir + "/out/pair-energy.svg");
    ASSERT_FALSE(energy.empty());
    // Only the run that explodes is cut, and the title says so; the springs' energy counts.
    const std::size_t cut = energy.find("off this scale, cut at its edge: ");
    EXPECT_EQ(cut != std::string::npos, explode) << energy.substr(0, 2000);
    if (explode) {
      EXPECT_NE(energy.find("course/explicit-euler (reaches", cut), std::string::npos);
      EXPECT_EQ(energy.find("course/rk4 (reaches", cut), std::string::npos);
      EXPECT_NE(energy.find("gravitational + spring"), std::string::npos);
    }
  }
}

// The trajectories too: explicit Euler's exploding spring set the axes (thousands of
// metres on the spring grids), so every other run collapsed into a dot. The axes come from
// the reference and the runs near it; the run that leaves is cut at the axis and named.
TEST(Plots, AnExplodingRunIsCutAtTheTrajectoryAxesAndNamed) {
  for (const bool explode : {false, true}) {
    const std::string dir = test::fresh_dir(explode ? "path_cut" : "path_whole");
    const std::string path = test::write_case(dir, "pair.toml", falling_pair(false, explode));
    const test::Outcome o = test::beachball(
        "run " + path + " --no-cost --backends reference,course/explicit-euler,course/rk4 --out " +
        dir + "/out");
    ASSERT_EQ(o.exit_code, 0) << o.out;
    const std::string trajectory = svg_of(dir + "/out/pair-trajectory.svg");
    ASSERT_FALSE(trajectory.empty());
    const std::size_t cut = trajectory.find("off this scale, cut at its edge: ");
    EXPECT_EQ(cut != std::string::npos, explode) << trajectory.substr(0, 3000);
    if (!explode) continue;
    EXPECT_NE(trajectory.find("course/explicit-euler (reaches", cut), std::string::npos);
    EXPECT_EQ(trajectory.find("course/rk4 (reaches", cut), std::string::npos);
    // Every axis spans what the reference does, give or take: the balls fall 100 m, the
    // bob swings by a metre; no tic reads thousands.
    for (const test::SvgText& t : test::svg_texts(trajectory)) {
      const bool tic = t.anchor == "end" && !t.turned &&
                       t.text.find_first_not_of(" -.0123456789e+") == std::string::npos;
      if (tic) {
        EXPECT_LE(std::abs(std::stod(t.text)), 200.0) << "a tic at " << t.text;
      }
    }
  }
}

// A drawing is kept with the results: the same script and data are not drawn again (gnuplot
// out of reach, the kept SVG is written all the same), other data or --fresh draws anew.
TEST(KeptDrawings, TheSameScriptAndDataAreNotDrawnAgain) {
  BB_SKIP_IF_MISSING(
      gnuplot_available() ? "" : "gnuplot is not installed (scripts/setup installs gnuplot-nox)");
  const std::string dir = test::fresh_dir("kept_drawings");
  const ResultCache cache(dir + "/cache", 1 << 20);
  const std::string script = "plot data using 1:2 with lines\n", data = "0 0\n1 1\n";
  const auto drawn = [&](const std::string& folder, const std::string& rows) {
    fs::create_directories(folder);
    FileBatch batch(folder);
    draw(script, rows, batch, "p.svg");
    batch.commit();
    return test::bytes(folder + "/p.svg");
  };
  std::string first;
  {
    const KeptDrawings keep(&cache, true);
    first = drawn(dir + "/first", data);
  }
  ASSERT_NE(first.find("</svg>"), std::string::npos);
  // Without gnuplot on the PATH only a kept drawing can be written.
  struct NoPath {
    const std::string path = std::getenv("PATH");
    NoPath() { setenv("PATH", "/nonexistent", 1); }
    ~NoPath() { setenv("PATH", path.c_str(), 1); }
  } no_gnuplot;
  {
    const KeptDrawings keep(&cache, true);
    EXPECT_EQ(drawn(dir + "/again", data), first);
    EXPECT_THROW(drawn(dir + "/other", "0 0\n1 2\n"), WriteError);
  }
  {
    const KeptDrawings fresh(&cache, false);
    EXPECT_THROW(drawn(dir + "/fresh", data), WriteError);
  }
  EXPECT_THROW(drawn(dir + "/none", data), WriteError);
}

}  // namespace
}  // namespace bb
