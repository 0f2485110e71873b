// Seed section 3, "Three beachballs 1": the order of the two Euler updates and the floor
// rule decide whether a bouncing ball keeps, gains or loses its energy.
#include <gtest/gtest.h>

#include <algorithm>

#include "course/course_backend.hpp"
#include "model/motion.hpp"
#include "study/start_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

// The seed's demo: a unit ball dropped on the floor, the velocity reversed at the floor.
const char* kThreeBeachballs = R"(name = "three_beachballs_1"
dims = 2
duration = 60.0
sample = 0.0166666666666666667
dt = [0.0166666666666666667]
report_dt = 0.0166666666666666667

[ground]
restitution = 1.0

[[body]]
name = "ball"
radius = 1.0
mass = 1.0
position = [0.0, 5.0, 0.0]
)";

/// Apex heights (centre, m) and the final state of one variant over the whole run.
struct Bounces {
  std::vector<double> apexes;
  BodyState end;
  double lowest = 1e300;
};

Bounces bounce(const Scene& scene, const std::string& integrator, const std::string& rule) {
  const CourseBackend backend({"course", integrator, rule, "clamp"});
  const double dt = scene.report_dt;
  auto sim = start_case(backend, scene, dt);
  State s(1);
  Bounces out;
  double previous_vy = 0.0;
  for (long n = 0; n < std::lround(scene.duration / dt); ++n) {
    sim->step();
    sim->read(s);
    // An apex is the step where the vertical velocity turns from up to down.
    if (previous_vy > 0.0 && s[0].velocity.y() <= 0.0) out.apexes.push_back(s[0].position.y());
    previous_vy = s[0].velocity.y();
    out.lowest = std::min(out.lowest, s[0].position.y());
  }
  out.end = s[0];
  return out;
}

TEST(ThreeBeachballs, TheSeedsStoryHoldsInNumbers) {
  const Scene scene = test::scene_from(kThreeBeachballs);
  const double drop = scene.bodies[0].position.y(), r = scene.bodies[0].radius;
  // Left ball: semi-implicit Euler, moved up to touch the floor. Its apex stays in a band.
  const Bounces left = bounce(scene, "semi-implicit-euler", "clamp");
  ASSERT_GT(left.apexes.size(), 20u);
  for (double apex : left.apexes) EXPECT_NEAR(apex, drop, 0.05 * (drop - r));
  // Middle ball: explicit Euler with the same floor: it gains energy.
  const Bounces middle = bounce(scene, "explicit-euler", "clamp");
  ASSERT_GT(middle.apexes.size(), 5u);
  EXPECT_GT(middle.apexes.back(), middle.apexes.front() + 0.5);
  // Right ball: semi-implicit Euler, velocity reversed only: it loses energy and sinks.
  const Bounces right = bounce(scene, "semi-implicit-euler", "reflect");
  EXPECT_LT(right.end.position.y(), 0.0) << "ends below the floor";
}

}  // namespace
}  // namespace bb
