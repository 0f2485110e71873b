// The motion view draws every moving body of every backend, animated by the SVG itself, the
// fixed bodies once, and stays under its size limit however many bodies, backends and
// samples a case has; a scene of many bodies gets a panel per backend over the reference.
#include "report/motion_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "report/backend_style.hpp"
#include "run/drawn_bodies.hpp"
#include "run/engine_catalogue.hpp"
#include "scene/backend_names.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// A run at report_dt whose bodies fall from their start, `lag` behind free fall, for
/// `samples` samples.
RunRecord falling_run(const Scene& scene, const std::string& backend, std::size_t samples,
                      double lag) {
  RunRecord run;
  run.backend = backend;
  if (backend != "reference") run.dt = scene.report_dt;
  const std::vector<int> drawn = drawn_bodies(scene);
  for (std::size_t j = 0; j < samples; ++j) {
    const double t = j * scene.sample;
    run.trajectory.times.push_back(t);
    State s;
    for (int b : drawn) {
      BodyState body;
      body.position = scene.bodies[b].position;
      if (!scene.bodies[b].fixed) body.position.y() -= 0.5 * 9.81 * t * t * (1.0 - lag);
      s.push_back(body);
    }
    run.trajectory.states.push_back(s);
  }
  return run;
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

/// A run whose block slides along the ground to `to` metres, at an even speed.
RunRecord sliding_run(const Scene& scene, const std::string& backend, double to) {
  RunRecord run;
  run.backend = backend;
  if (backend != "reference") run.dt = scene.report_dt;
  for (std::size_t j = 0; j <= 200; ++j) {
    const double t = j * scene.sample;
    BodyState block;
    block.position = scene.bodies[0].position + Vec3(to * t / scene.duration, 0.0, 0.0);
    run.trajectory.times.push_back(t);
    run.trajectory.states.push_back({block});
  }
  return run;
}

/// Every "x y" pair of numbers after an M or an L in `text` (path data, in order).
std::vector<std::pair<double, double>> points_of(const std::string& text) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t m = text.find_first_of("ML", at);
    if (m == std::string::npos) break;
    char* end = nullptr;
    const double x = std::strtod(text.c_str() + m + 1, &end);
    if (end != text.c_str() + m + 1 && *end == ' ') {
      char* end_y = nullptr;
      const double y = std::strtod(end + 1, &end_y);
      if (end_y != end + 1) out.push_back({x, y});
    }
    at = m + 1;
  }
  return out;
}

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

TEST(BackendStyle, EveryBackendOfEveryBundledCaseHasAColourOfItsOwnInItsCase) {
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("cases"))) {
    const Scene scene = load_case(entry.path().string());
    std::set<std::string> names;
    for (const std::string& name : backend_names(scene, engine_catalogue())) names.insert(name);
    names.insert("reference");
    std::set<std::string> colours;
    for (const std::string& name : names) {
      const BackendStyle style = backend_style(name);
      EXPECT_EQ(style.colour, backend_style(name).colour);
      EXPECT_TRUE(colours.insert(style.colour).second)
          << scene.name << ": " << name << " shares " << style.colour;
    }
  }
}

}  // namespace
}  // namespace bb
