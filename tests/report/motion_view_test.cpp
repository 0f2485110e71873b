// The motion view draws every moving body of every backend, animated by the SVG itself, the
// fixed bodies once, and stays under its size limit however many bodies, backends and
// samples a case has; a scene of many bodies gets a panel per backend over the reference.
#include "report/motion_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
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
