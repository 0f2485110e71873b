// Sailing (seed section 9, "Boat 1") through the force model: the sail's push against its
// formula square-on and edge-on; the sail's and the hull's derivatives against finite
// differences (keel, no drift, heel); downwind with no drift, the reference against the
// closed form of m v' = a (w - v)^2 - b v^2 and the course's Euler at order 1; and no drift
// on every backend in a side wind.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "course/course_backend.hpp"
#include "model/motion.hpp"
#include "physics/force_model.hpp"
#include "physics/state_forces.hpp"
#include "run/case_runner.hpp"
#include "study/start_case.hpp"
#include "support/engine_support.hpp"
#include "support/jacobian_support.hpp"
#include "support/test_support.hpp"

namespace bb {
namespace {

/// One boat of 200 kg heading along x (`heading` degrees about z) in a wind, with `sail` and
/// `hull` lines under their tables.
std::string boat_case(const std::string& wind, double heading, const std::string& sail,
                      const std::string& hull, const std::string& velocity = "[0.0, 0.0, 0.0]") {
  return R"(name = "boat"
dims = 2
duration = 12.0
sample = 0.1
dt = [0.1, 0.05]
report_dt = 0.05
gravity = [0.0, 0.0, 0.0]
[air]
density = 1.2
wind = )" +
         wind +
         R"(
[water]
density = 1025.0
[[body]]
name = "boat"
shape = "box"
half_extents = [2.0, 0.75, 0.5]
mass = 200.0
angle = )" +
         std::to_string(heading) + "\nvelocity = " + velocity + "\n[body.sail]\n" + sail +
         "\n[body.hull]\n" + hull + "\n";
}

Vec3 force_on_boat(const Scene& scene, const Vec3& velocity) {
  State s = initial_state(scene);
  s[0].velocity = velocity;
  StateForces forces(scene);
  return forces.at(s).force[0];
}

TEST(Sailing, TheSailIsPushedAlongItsNormalSquareOnAndNotAtAllEdgeOn) {
  const std::string no_hull = "forward = 0.0\nsideways = 0.0";
  // Sail square to the heading, wind from astern: F = 1/2 rho C A w^2 along the heading.
  const Scene square = test::scene_from(
      boat_case("[8.0, 0.0, 0.0]", 0.0, "area = 10.0\ncoefficient = 1.2\nangle = 90.0", no_hull));
  const Vec3 f = force_on_boat(square, Vec3::Zero());
  EXPECT_NEAR(f.x(), 0.5 * 1.2 * 1.2 * 10.0 * 64.0, 1e-9);
  EXPECT_NEAR(f.y(), 0.0, 1e-12);
  // The same sail along the heading, the wind along it too: edge-on, no push.
  const Scene edge = test::scene_from(
      boat_case("[8.0, 0.0, 0.0]", 0.0, "area = 10.0\ncoefficient = 1.2\nangle = 0.0", no_hull));
  EXPECT_LT(force_on_boat(edge, Vec3::Zero()).norm(), 1e-12);
  // At 45 degrees in a side wind from port the push is w^2 sin^2(45) of the square-on one,
  // along the normal that points ahead and to starboard (the boom out to leeward).
  const Scene side = test::scene_from(
      boat_case("[0.0, -8.0, 0.0]", 0.0, "area = 10.0\ncoefficient = 1.2\nangle = 45.0", no_hull));
  const Vec3 g = force_on_boat(side, Vec3::Zero());
  const double push = 0.5 * 1.2 * 1.2 * 10.0 * 32.0;
  EXPECT_NEAR(g.x(), push / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(g.y(), -push / std::sqrt(2.0), 1e-9);
}

TEST(Sailing, TheDerivativesOfSailAndHullMatchFiniteDifferences) {
  // Along the heading (20 degrees: 1.2 tan(20 degrees) across) with no drift; else with a
  // drift, away from the kink of u |u| at u = 0 that central differences cannot follow.
  const std::string along = "[1.2, 0.43676428111944282, 0.0]", drifting = "[1.2, 0.1, 0.0]";
  struct Boat {
    std::string sail, hull, velocity;
  };
  for (const Boat& boat :
       {Boat{"area = 10.0\nangle = 30.0", "forward = 0.05\nbackward = 0.2\nsideways = 2.0",
             drifting},
        Boat{"area = 10.0\nangle = 30.0", "forward = 0.05\nno_drift = true", along},
        Boat{"area = 10.0\nangle = 30.0\nheel_stiffness = 300.0", "forward = 0.05\nsideways = 2.0",
             drifting}}) {
    SCOPED_TRACE(boat.sail + " / " + boat.hull);
    const Scene scene =
        test::scene_from(boat_case("[-3.0, -7.0, 0.0]", 20.0, boat.sail, boat.hull, boat.velocity));
    test::expect_velocity_derivative_matches(
        scene, initial_state(scene), [&](const Vec3& v) { return force_on_boat(scene, v); }, 1e-5);
  }
}

/// Downwind, no drift: m v' = a (w - v)^2 - b v^2 from rest has the roots v* and v2 of its
/// right side, and (v - v*) / (v - v2) = (v*/v2) exp((a - b) (v* - v2) t / m).
double downwind_speed(double a, double b, double w, double m, double t) {
  const double r = std::sqrt(b / a);
  const double v_star = w / (1.0 + r), v_two = w / (1.0 - r);
  const double c = (v_star / v_two) * std::exp((a - b) * (v_star - v_two) * t / m);
  return (v_star - c * v_two) / (1.0 - c);
}

TEST(Sailing, DownwindTheReferenceFollowsTheClosedFormAndEulerConvergesAtOrderOne) {
  const Scene scene = test::scene_from(
      boat_case("[8.0, 0.0, 0.0]", 0.0, "area = 10.0\ncoefficient = 1.2\nangle = 90.0",
                "forward = 0.05\nbackward = 0.2\nno_drift = true"));
  const double a = 0.5 * 1.2 * 1.2 * 10.0, b = 0.5 * 1025.0 * 0.05;
  const auto speed_after = [&](const Backend& backend, double dt, int steps) {
    std::unique_ptr<Simulation> sim = start_case(backend, scene, dt);
    for (int n = 0; n < steps; ++n) sim->step();
    State out(1);
    sim->read(out);
    return out[0].velocity.x();
  };
  for (double t : {0.5, 2.0, 8.0}) {
    const double exact = downwind_speed(a, b, 8.0, 200.0, t);
    EXPECT_NEAR(speed_after(test::registry().reference(), 0.1, static_cast<int>(t / 0.1 + 0.5)),
                exact, 1e-9)
        << "t = " << t;
  }
  // It never reaches the wind: the steady speed is w / (1 + sqrt(b / a)), well below 8 m/s.
  EXPECT_LT(8.0 / (1.0 + std::sqrt(b / a)), 8.0);
  const CourseBackend euler(
      {"course/semi-implicit-euler", "semi-implicit-euler", "mirror", "clamp"});
  const double exact = downwind_speed(a, b, 8.0, 200.0, 2.0);
  const double coarse = std::abs(speed_after(euler, 0.02, 100) - exact);
  const double fine = std::abs(speed_after(euler, 0.01, 200) - exact);
  EXPECT_NEAR(std::log2(coarse / fine), 1.0, 0.05);
}

TEST(Sailing, WithNoDriftEveryBackendGoesWhereItHeadsInASideWind) {
  const Scene scene = test::scene_from(boat_case(
      "[0.0, -8.0, 0.0]", 30.0, "area = 10.0\nangle = 45.0", "forward = 0.05\nno_drift = true"));
  BackendSet set = backends_for(scene, test::registry());
  std::vector<const Backend*> backends = set.all;
  backends.push_back(&test::registry().reference());
  const Vec3 across = scene.bodies[0].orientation * Vec3(0.0, 1.0, 0.0);
  ASSERT_GE(backends.size(), 5u);
  for (const Backend* backend : backends) {
    SCOPED_TRACE(backend->name());
    std::unique_ptr<Simulation> sim = start_case(*backend, scene, 0.05);
    State out(1);
    for (int n = 0; n < 240; ++n) sim->step();
    sim->read(out);
    // It gets going ahead; across, only rounding (a float engine's is larger).
    EXPECT_GT(out[0].velocity.norm(), 0.5);
    const bool single = test::single_precision(backend->name());
    EXPECT_LT(std::abs(out[0].velocity.dot(across)), single ? 1e-4 : 1e-9);
  }
}

}  // namespace
}  // namespace bb
