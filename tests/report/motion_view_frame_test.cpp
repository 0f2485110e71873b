// The motion view frames what it can show: a backend a few metres from the reference is
// framed with the others, while one that leaves the frame far behind (a slide of 50 m, a
// divergence to 1e30 m) is cut, marked at the edge it left by and named with where it went,
// without shrinking the others.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "report/backend_style.hpp"
#include "report/motion_view.hpp"
#include "run/drawn_bodies.hpp"
#include "support/motion_runs.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::points_of;
using test::sliding_run;

const char* kBlockOnTheGround = R"(name = "slide"
dims = 2
duration = 2.0
sample = 0.01
dt = [0.01]
report_dt = 0.01
[ground]
[[body]]
name = "block"
shape = "box"
half_extents = [0.25, 0.25, 0.25]
mass = 1.0
position = [0.0, 0.25, 0.0]
)";

/// The frame-exit marks of `svg`, each its text.
std::vector<std::string> exit_marks(const std::string& svg) {
  std::vector<std::string> out;
  for (std::size_t at = svg.find("class=\"frame-exit\""); at != std::string::npos;
       at = svg.find("class=\"frame-exit\"", at + 1))
    out.push_back(svg.substr(at, svg.find("</g>", at) - at));
  return out;
}

// A block that slides far out of the reference's frame on one backend (50 m, where the
// reference and the others hold it still) does not vanish: the view frames the others, an
// arrow in that backend's colour points out at the edge where the block left (right: it
// slid in +x) with the body and the time, and the title names the run and where it went.
// In the still, the mark is in the panels of the instants after it left.
TEST(MotionView, ABlockThatSlidesOutOfTheFrameIsMarkedAtTheEdgeAndNamed) {
  const Scene scene = test::scene_from(kBlockOnTheGround);
  CaseResults results;
  results.scene = &scene;
  results.reference_run = sliding_run(scene, "reference", 0.0);
  results.runs = {sliding_run(scene, "course/rk4", 0.0), sliding_run(scene, "ode", 0.01),
                  sliding_run(scene, "bullet", 50.0)};
  const std::string svg = motion_svg(results, drawn_bodies(scene));
  const std::vector<std::string> marks = exit_marks(svg);
  ASSERT_EQ(marks.size(), 1u) << svg.substr(0, 3000);
  EXPECT_NE(marks[0].find(backend_style("bullet").colour), std::string::npos) << marks[0];
  EXPECT_NE(marks[0].find("block left at"), std::string::npos) << marks[0];
  // The arrow's tip (its path's second point) at the canvas's right edge.
  const auto arrow = points_of(marks[0].substr(marks[0].find("d=\"")));
  ASSERT_GE(arrow.size(), 2u);
  EXPECT_GT(arrow[1].first, 0.95 * 760.0);
  EXPECT_GT(arrow[1].first, arrow[0].first) << "the arrow points out, to the right";
  EXPECT_NE(svg.find("bullet: block left at t = "), std::string::npos);
  EXPECT_NE(svg.find("reaches (50, 0.25) m"), std::string::npos);
  // It appears when the block leaves, not before.
  EXPECT_NE(marks[0].find("attributeName=\"opacity\" values=\"0;1\""), std::string::npos);

  const std::vector<double> instants = still_instants(scene);
  const std::string still = motion_still_svg(results, drawn_bodies(scene), instants);
  // The block leaves the frame early (a frame a few metres wide, 25 m/s): every instant
  // after the start shows the mark, the start does not.
  EXPECT_EQ(exit_marks(still).size(), instants.size() - 1);
  EXPECT_NE(still.find("bullet: block left at t = "), std::string::npos);
}

// A backend that slides its block a few metres from the reference's still one is within
// reason: the view frames it, every point of it inside the canvas, and nothing is marked.
TEST(MotionView, ABackendAFewMetresAwayIsFramedNotCut) {
  const Scene scene = test::scene_from(kBlockOnTheGround);
  CaseResults results;
  results.scene = &scene;
  results.reference_run = sliding_run(scene, "reference", 0.0);
  results.runs = {sliding_run(scene, "course/rk4", 0.0), sliding_run(scene, "bullet", 3.0)};
  const std::string svg = motion_svg(results, drawn_bodies(scene));
  EXPECT_TRUE(exit_marks(svg).empty());
  // The canvas: the panel's viewBox.
  const std::size_t box = svg.find("viewBox=\"0 0 ", svg.find("<svg x="));
  ASSERT_NE(box, std::string::npos);
  char* end = nullptr;
  const double width = std::strtod(svg.c_str() + box + 13, &end);
  const double height = std::strtod(end + 1, nullptr);
  const std::size_t run = svg.find(backend_style("bullet").colour);
  ASSERT_NE(run, std::string::npos);
  const std::string drawn = svg.substr(run, svg.find("</g>", run) - run);
  const auto points = points_of(drawn);
  ASSERT_FALSE(points.empty());
  for (const auto& [x, y] : points) {
    EXPECT_GE(x, 0.0);
    EXPECT_LE(x, width);
    EXPECT_GE(y, 0.0);
    EXPECT_LE(y, height);
  }
}

// A run that diverged to 1e30 m and then to NaN does not shrink the view to nothing: the
// others are drawn at the size they have without it, and it is named with where it went.
TEST(MotionView, ADivergedRunFarAwayIsCutNamedAndDoesNotShrinkTheView) {
  const Scene scene = test::scene_from(kBlockOnTheGround);
  CaseResults results;
  results.scene = &scene;
  results.reference_run = sliding_run(scene, "reference", 1.0);
  results.runs = {sliding_run(scene, "course/rk4", 1.0)};
  const std::string calm = motion_svg(results, drawn_bodies(scene));
  RunRecord wild = sliding_run(scene, "course/explicit-euler", 1.0);
  wild.status = RunStatus::Diverged;
  for (std::size_t j = 100; j < wild.trajectory.states.size(); ++j)
    wild.trajectory.states[j][0].position =
        j < 150 ? Vec3(1e30, -1e29, 0.0) : Vec3::Constant(std::nan(""));
  results.runs.push_back(wild);
  const std::string svg = motion_svg(results, drawn_bodies(scene));
  // The reference's block (the first animated path) is as big as without the wild run.
  const auto first_path = [](const std::string& text) {
    const std::size_t at = text.find("<path><animate attributeName=\"d\" values=\"");
    return points_of(text.substr(at, text.find(';', at) - at));
  };
  const auto before = first_path(calm), after = first_path(svg);
  ASSERT_EQ(before.size(), 4u);
  ASSERT_EQ(after.size(), 4u);
  EXPECT_NEAR(after[1].first - after[0].first, before[1].first - before[0].first, 1e-6);
  EXPECT_GT(after[1].first - after[0].first, 20.0) << "the block is drawn at a visible size";
  const std::vector<std::string> marks = exit_marks(svg);
  ASSERT_EQ(marks.size(), 1u);
  EXPECT_NE(svg.find("course/explicit-euler (diverged): block left at t = 1 s, reaches (1e+30, "
                     "-1e+29) m, not a number from t = 1.5 s"),
            std::string::npos)
      << svg.substr(0, 2000);
}

}  // namespace
}  // namespace bb
