// The motion view draws every moving body of every backend, animated by the SVG itself, the
// fixed bodies once, and stays under its size limit however many bodies, backends and
// samples a case has; a scene of many bodies gets a panel per backend over the reference;
// a boat and a rope are drawn as what they are. (Framing: motion_view_frame_test.cpp.)
#include "report/motion_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <set>

#include "report/backend_style.hpp"
#include "run/drawn_bodies.hpp"
#include "run/engine_catalogue.hpp"
#include "study/backend_names.hpp"
#include "support/motion_runs.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

using test::falling_run;
using test::points_of;
using test::sliding_run;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

const char* kTwoBallsAndAWall = R"(name = "two_balls"
dims = 2
duration = 1.0
sample = 0.01
dt = [0.01]
report_dt = 0.01
[ground]
restitution = 0.5
[[body]]
name = "a"
radius = 0.5
mass = 1.0
position = [0.0, 5.0, 0.0]
[[body]]
name = "b"
radius = 0.25
mass = 1.0
position = [2.0, 5.0, 0.0]
[[body]]
name = "wall"
shape = "box"
half_extents = [0.1, 2.0, 0.5]
position = [4.0, 2.0, 0.0]
fixed = true
[[contact]]
bodies = ["a", "wall"]
restitution = 0.5
)";

TEST(MotionView, EveryMovingBodyOfEveryRunIsAnimatedAndTheFixedOnesDrawnOnce) {
  const Scene scene = test::scene_from(kTwoBallsAndAWall);
  CaseResults results;
  results.scene = &scene;
  results.reference_run = falling_run(scene, "reference", 101, 0.0);
  results.runs = {falling_run(scene, "course/explicit-euler", 101, 0.1),
                  falling_run(scene, "bullet", 101, 0.05)};
  const std::string svg = motion_svg(results, drawn_bodies(scene));
  // Two moving balls in three runs, each moving in x and y.
  EXPECT_EQ(count(svg, "<circle r="), 6) << svg.substr(0, 2000);
  EXPECT_EQ(count(svg, "attributeName=\"cy\""), 6);
  // The wall is one static path; the ground is drawn.
  EXPECT_EQ(count(svg, "fill=\"#8a8a8a\""), 1);
  EXPECT_NE(svg.find("#efe6d6"), std::string::npos);
  // It plays by itself, without script.
  EXPECT_NE(svg.find("repeatCount=\"indefinite\""), std::string::npos);
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  // Each backend in its own colour.
  for (const char* b : {"course/explicit-euler", "bullet"})
    EXPECT_NE(svg.find(backend_style(b).colour), std::string::npos) << b;
  EXPECT_NE(svg.find("the reference filled grey"), std::string::npos);
}

TEST(MotionView, ARunThatEndsEarlyHoldsItsLastStateAndFades) {
  const Scene scene = test::scene_from(kTwoBallsAndAWall);
  CaseResults results;
  results.scene = &scene;
  results.reference_run = falling_run(scene, "reference", 101, 0.0);
  results.runs = {falling_run(scene, "course/explicit-euler", 40, 0.0)};
  results.runs.back().status = RunStatus::Diverged;
  const std::string svg = motion_svg(results, drawn_bodies(scene));
  EXPECT_EQ(count(svg, "attributeName=\"opacity\" values=\"1;0.3\""), 1);
  EXPECT_NE(svg.find("course/explicit-euler (diverged)"), std::string::npos);
}

TEST(MotionView, WithoutAReferenceItSaysSoAndDrawsNoGhost) {
  const Scene scene = test::scene_from(kTwoBallsAndAWall);
  CaseResults results;
  results.scene = &scene;
  results.reference_run.backend = "reference";
  results.reference_run.status = RunStatus::Unsupported;
  results.runs = {falling_run(scene, "course/rk4", 101, 0.0)};
  const std::string svg = motion_svg(results, drawn_bodies(scene));
  EXPECT_NE(svg.find("the reference has no answer here"), std::string::npos);
  EXPECT_EQ(svg.find("filled grey"), std::string::npos);
}

TEST(MotionView, AGridOfManyRunsStaysUnderTheLimitInPanelsOverTheReference) {
  // A 3D grid of 8 x 8 x 8 particles (more than are kept), thirteen runs, a long run.
  std::string text = R"(name = "big_grid"
dims = 3
duration = 20.0
sample = 0.01
dt = [0.01]
report_dt = 0.01
[grid]
size = [8, 8, 8]
spacing = 0.5
mass = 0.1
neighbours = 26
stiffness = 50.0
damping = 0.2
origin = [0.0, 10.0, 0.0]
)";
  const Scene scene = test::scene_from(text);
  const std::vector<int> drawn = drawn_bodies(scene);
  EXPECT_LE(drawn.size(), kDrawnBodies);
  CaseResults results;
  results.scene = &scene;
  results.reference_run = falling_run(scene, "reference", 2001, 0.0);
  const std::vector<std::string> names = engine_backend_names(engine_catalogue());
  for (int i = 0; i < 12; ++i)
    results.runs.push_back(falling_run(
        scene, i < static_cast<int>(names.size()) ? names[i] : "course/rk4", 2001, 0.01 * i));
  const std::string svg = motion_svg(results, drawn);
  EXPECT_LT(svg.size(), kMotionViewBytes);
  // The reference drawn once and used under each of the thirteen panels.
  EXPECT_EQ(count(svg, "<g id=\"reference\">"), 1);
  EXPECT_EQ(count(svg, "xlink:href=\"#reference\""), 13);
  const std::string still = motion_still_svg(results, drawn, still_instants(scene));
  EXPECT_LT(still.size(), kMotionViewBytes);
  // A row per run, named above its four instants.
  EXPECT_EQ(count(still, "font-size=\"14\""), 13);
  EXPECT_EQ(count(still, "xlink:href=\"#reference-"), 4 * 13);
}

// A boat seen from above is drawn as one: its hull pointed at its bow (the heading), its
// sail a line from the mast out to leeward at the sail's angle from the heading, and the
// wind an arrow with its speed (three tiny boxes said none of it).
TEST(MotionView, ABoatShowsItsHeadingItsSailAndTheWind) {
  const Scene scene = test::scene_from(R"(name = "boat"
dims = 2
duration = 2.0
sample = 0.01
dt = [0.01]
report_dt = 0.01
gravity = [0.0, 0.0, 0.0]
[air]
density = 1.2
wind = [-5.656854249492380, -5.656854249492380, 0.0]
[water]
density = 1025.0
[[body]]
name = "boat"
shape = "box"
half_extents = [2.0, 0.75, 0.5]
mass = 200.0
position = [0.0, 0.0, 0.0]
[body.sail]
area = 10.0
coefficient = 1.2
angle = 15.0
[body.hull]
forward = 0.05
backward = 0.2
sideways = 2.0
)");
  CaseResults results;
  results.scene = &scene;
  results.reference_run = sliding_run(scene, "reference", 3.0);
  const std::string still = motion_still_svg(results, drawn_bodies(scene), {0.0});
  // The boat's outline: the hull's five points, then the mast and the sail's end.
  const std::size_t at = still.find("<path d=\"M", still.find("<g fill=\"#cfcfcf\""));
  ASSERT_NE(at, std::string::npos);
  const auto p = points_of(still.substr(at, still.find("/>", at) - at));
  ASSERT_EQ(p.size(), 7u) << still.substr(at, 300);
  // The bow: ahead (+x, the heading) of every other point of the hull, on its middle line.
  for (int i : {0, 1, 3, 4}) EXPECT_GT(p[2].first, p[i].first + 1.0);
  EXPECT_NEAR(p[2].second, (p[0].second + p[4].second) / 2, 0.2);
  // The sail: from the mast aft at 15 degrees from the heading, to leeward (the wind blows
  // to -y; on the page, y down, that is down).
  const double ax = p[6].first - p[5].first, ay = p[6].second - p[5].second;
  EXPECT_LT(ax, 0.0) << "the boom points aft";
  EXPECT_GT(ay, 0.0) << "the boom is out to leeward";
  EXPECT_NEAR(std::atan2(ay, -ax) * 180.0 / 3.141592653589793, 15.0, 1.0);
  // The wind's arrow points the way it blows (page: left and down), with its speed.
  const std::size_t wind = still.find("class=\"wind\"");
  ASSERT_NE(wind, std::string::npos);
  const auto w = points_of(still.substr(wind, still.find("</g>", wind) - wind));
  ASSERT_GE(w.size(), 2u);
  EXPECT_LT(w[1].first - w[0].first, 0.0);
  EXPECT_GT(w[1].second - w[0].second, 0.0);
  EXPECT_NE(still.find("wind 8 m/s"), std::string::npos);
}

// A rope (a grid of one row) is drawn with its springs: a line from each particle to the
// next, at their centres.
TEST(MotionView, ARopesSpringsAreLinesBetweenItsParticles) {
  const Scene scene = test::scene_from(R"(name = "rope"
dims = 2
duration = 1.0
sample = 0.01
dt = [0.01]
report_dt = 0.01
[grid]
size = [5, 1]
spacing = 0.5
mass = 0.1
neighbours = 4
stiffness = 50.0
damping = 0.2
origin = [0.0, 3.0, 0.0]
)");
  CaseResults results;
  results.scene = &scene;
  results.reference_run = falling_run(scene, "reference", 101, 0.0);
  const std::string still = motion_still_svg(results, drawn_bodies(scene), {0.0});
  std::vector<std::pair<double, double>> centres;
  for (std::size_t at = still.find("<circle cx=\""); at != std::string::npos;
       at = still.find("<circle cx=\"", at + 1)) {
    char* end = nullptr;
    const double x = std::strtod(still.c_str() + at + 12, &end);
    centres.push_back({x, std::strtod(end + 6, nullptr)});
  }
  ASSERT_EQ(centres.size(), 5u);
  const std::size_t springs = still.find("<path d=\"M");
  ASSERT_NE(springs, std::string::npos);
  const auto p = points_of(still.substr(springs, still.find("\"", springs + 9) - springs));
  ASSERT_EQ(p.size(), 8u) << "four springs, two ends each";
  for (std::size_t s = 0; s < 4; ++s) {
    EXPECT_NEAR(std::hypot(p[2 * s].first - centres[s].first, p[2 * s].second - centres[s].second),
                0.0, 0.11);
    EXPECT_NEAR(std::hypot(p[2 * s + 1].first - centres[s + 1].first,
                           p[2 * s + 1].second - centres[s + 1].second),
                0.0, 0.11);
  }
}

TEST(DrawnBodies, ASmallSceneKeepsEveryBodyAndABigGridALatticeWithItsCorners) {
  const Scene small = test::scene_from(kTwoBallsAndAWall);
  EXPECT_EQ(drawn_bodies(small), (std::vector<int>{0, 1, 2}));
  const Scene grid = test::scene_from(R"(name = "g"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1]
report_dt = 0.1
[grid]
size = [30, 20]
spacing = 0.5
mass = 0.1
neighbours = 4
stiffness = 50.0
damping = 0.2
origin = [0.0, 10.0, 0.0]
)");
  const std::vector<int> drawn = drawn_bodies(grid);
  EXPECT_LE(drawn.size(), kDrawnBodies);
  EXPECT_GE(drawn.size(), kDrawnBodies / 2);
  const std::set<int> kept(drawn.begin(), drawn.end());
  const int first = grid.grid->first_body;
  for (int corner : {first, first + 29, first + 19 * 30, first + 19 * 30 + 29})
    EXPECT_TRUE(kept.count(corner)) << corner;
  EXPECT_EQ(kept.size(), drawn.size()) << "a body kept twice";
}

}  // namespace
}  // namespace bb
