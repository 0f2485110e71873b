// "Push" (seed section 2): the same impulse on two masses gives each J/m, applied at the
// start of the step that begins at the impulse's time.
#include <gtest/gtest.h>

#include "course/course_backend.hpp"
#include "study/start_case.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

TEST(CourseImpulse, EveryIntegratorGivesJOverMAtTheImpulsesTime) {
  const Scene scene = test::scene_from(R"(name = "push"
dims = 2
duration = 1.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05
gravity = [0.0, 0.0, 0.0]

[[body]]
name = "left"
radius = 0.5
mass = 1.0
position = [-1.0, 0.0, 0.0]

[[body]]
name = "right"
radius = 0.5
mass = 4.0
position = [1.0, 0.0, 0.0]

[[impulse]]
body = "left"
time = 0.2
impulse = [-2.0, 0.0, 0.0]

[[impulse]]
body = "right"
time = 0.2
impulse = [2.0, 0.0, 0.0]
)");
  for (const std::string& integrator : known_integrators()) {
    const CourseBackend backend({"course", integrator, "mirror", "clamp"});
    auto sim = start_case(backend, scene, 0.05);
    State s(2);
    // Four steps bring the run to t = 0.2 s: nothing has happened yet.
    for (int i = 0; i < 4; ++i) sim->step();
    sim->read(s);
    EXPECT_EQ(s[0].velocity.x(), 0.0) << integrator;
    // The fifth step starts at the impulse's time.
    sim->step();
    sim->read(s);
    EXPECT_EQ(s[0].velocity.x(), -2.0 / 1.0) << integrator;
    EXPECT_EQ(s[1].velocity.x(), 2.0 / 4.0) << integrator;
    // Momentum is what the two equal and opposite impulses gave: zero.
    EXPECT_EQ(s[0].velocity.x() * 1.0 + s[1].velocity.x() * 4.0, 0.0) << integrator;
  }
}

}  // namespace
}  // namespace bb
