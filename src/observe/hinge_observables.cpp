#include "observe/hinge_observables.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/hinge_motion.hpp"
#include "physics/state_forces.hpp"

namespace bb {

namespace {

/// The turn at which the hinge force is read, radians: 45 degrees.
constexpr double kTurn = std::numbers::pi / 4.0;

}  // namespace

const Hinge* hinge_of(const World& scene, int body) {
  for (const Hinge& h : scene.hinges)
    if (h.body == body) return &h;
  return nullptr;
}

Vec3 hinge_force(const Scene& scene, const Hinge& hinge, const BodyState& s, const Vec3& force) {
  const Body& body = scene.bodies[hinge.body];
  const Vec3 applied = body.mass * scene.gravity + force;
  const HingeAccelerations a =
      hinge_accelerations(body, s.orientation, s.position, s.angular_velocity, applied, hinge);
  return body.mass * a.linear - applied;
}

ObservableValue measure_hinge_force(const Scene& scene, const Observe& observe,
                                    const Trajectory& trajectory, const EventTrace*) {
  const Hinge* h = hinge_of(scene, observe.body);
  if (h == nullptr) return {std::nullopt, "the body is on no hinge"};
  const Quat start = scene.bodies[observe.body].orientation;
  // The turn from the start, radians, and the hinge force, at each sample in order.
  double turn_before = 0.0, force_before = 0.0;
  StateForces forces(scene);
  for (std::size_t n = 0; n < trajectory.states.size(); ++n) {
    const BodyState& s = trajectory.states[n][observe.body];
    const double turn =
        2.0 * std::acos(std::min(1.0, std::abs((start.conjugate() * s.orientation).w())));
    const Vec3& applied = forces.at(trajectory.states[n]).force[observe.body];
    const double force = hinge_force(scene, *h, s, applied).norm();
    if (n > 0 && turn >= kTurn && turn_before < kTurn)
      return {force_before + (force - force_before) * (kTurn - turn_before) / (turn - turn_before),
              ""};
    turn_before = turn, force_before = force;
  }
  return {std::nullopt, "it never turned 45 degrees"};
}

}  // namespace bb
