// A map coloured by an error (the bounce map's apex error): one scale for every backend, from
// the smallest positive error on the map to the largest, so the same error is the same colour
// in every panel and a larger one is darker; each ok cell is painted by its run's error.
#include "report/map_colour.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "report/map_picture.hpp"
#include "run/sweep_runner.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// A ball dropped from two heights at three steps, coloured by its first apex's error.
Scene bounce_map() {
  return test::scene_from(R"(name = "bounce"
dims = 2
duration = 3.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05
[ground]
restitution = 0.8
[[body]]
name = "ball"
radius = 0.5
mass = 1.0
position = [0.0, 10.0, 0.0]
[[observe]]
kind = "bounce_apex"
body = "ball"
n = 1
[[sweep]]
parameter = "body.ball.position.y"
values = [9.9, 10.3]
colour = "bounce_apex/ball/1"
[[sweep]]
parameter = "dt"
values = [0.1, 0.05, 0.025]
)");
}

/// A run of `backend` whose apex is `error` above the reference's (an ok run), or a
/// diverged one when `error` is negative.
RunRecord apex_run(const std::string& backend, double error) {
  RunRecord run;
  run.backend = backend;
  run.status = error < 0.0 ? RunStatus::Diverged : RunStatus::Ok;
  run.observables.push_back({"bounce_apex/ball/1", {error, ""}, 0.0});
  return run;
}

/// The relative luminance of "#rrggbb", 0 black to 1 white.
double luminance(const std::string& fill) {
  const auto channel = [&](int k) { return std::stoi(fill.substr(1 + 2 * k, 2), nullptr, 16); };
  return (0.2126 * channel(0) + 0.7152 * channel(1) + 0.0722 * channel(2)) / 255.0;
}

TEST(MapColour, OneScaleForEveryBackendFromTheSmallestErrorToTheLargest) {
  const Scene scene = bounce_map();
  CaseResults results;
  results.scene = &scene;
  results.sweep = SweepResults{"body.ball.position.y", sweep_points(scene), "dt"};
  // Course errors 1e-3 to 6e-3, an engine's 1e-2 to 6e-2 (one diverged), over the six points.
  for (std::size_t i = 0; i < results.sweep->points.size(); ++i) {
    SweepPoint& p = results.sweep->points[i];
    p.runs.push_back(apex_run("reference", 0.0));
    p.runs.push_back(apex_run("course/semi-implicit-euler", 1e-3 * static_cast<double>(i + 1)));
    p.runs.push_back(apex_run("bullet", i == 2 ? -1.0 : 1e-2 * static_cast<double>(i + 1)));
  }
  const MapScale scale = map_scale(results);
  EXPECT_EQ(scale.metric, "bounce_apex/ball/1");
  EXPECT_DOUBLE_EQ(scale.low, 1e-3);  // the reference's 0 has no place on a logarithmic scale
  EXPECT_DOUBLE_EQ(scale.high, 6e-2);
  EXPECT_TRUE(scale.logarithmic);
  // A larger error is darker, and the ends are the scale's ends.
  double previous = 2.0;
  for (double e : {1e-4, 1e-3, 3e-3, 1e-2, 3e-2, 6e-2}) {
    EXPECT_LE(luminance(scale_fill(scale, e)), previous) << e;
    previous = luminance(scale_fill(scale, e));
  }
  EXPECT_EQ(scale_fill(scale, 1e-4), scale_fill(scale, 1e-3));
  EXPECT_LT(luminance(scale_fill(scale, 6e-2)), 0.15);
  // Each panel paints its ok cells on that one scale: the course's 0.006 in its panel and
  // the engine's 0.01 and 0.06 in its own; the diverged cell keeps its outcome's colour.
  const std::string course = map_svg(results, "course/semi-implicit-euler");
  const std::string engine = map_svg(results, "bullet");
  EXPECT_NE(course.find("fill=\"" + scale_fill(scale, 6e-3) + "\""), std::string::npos);
  EXPECT_NE(engine.find("fill=\"" + scale_fill(scale, 1e-2) + "\""), std::string::npos);
  EXPECT_NE(engine.find("fill=\"" + scale_fill(scale, 6e-2) + "\""), std::string::npos);
  EXPECT_NE(engine.find("fill=\"#cb181d\"><title>"), std::string::npos);
  // Without a colour, no scale.
  Scene plain = scene;
  plain.sweep->colour.clear();
  results.scene = &plain;
  EXPECT_TRUE(map_scale(results).metric.empty());
}

}  // namespace
}  // namespace bb
