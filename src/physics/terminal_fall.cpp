#include "physics/terminal_fall.hpp"

#include <cmath>

#include "model/motion.hpp"
#include "physics/state_forces.hpp"

namespace bb {

std::optional<TerminalFall> terminal_fall(const World& scene, int body, std::string* why) {
  const auto fail = [&](const std::string& reason) -> std::optional<TerminalFall> {
    if (why) *why = reason;
    return std::nullopt;
  };
  const Body& b = scene.bodies[body];
  const double g = scene.gravity.norm();
  if (g <= 0.0) return fail("the case has no gravity");
  const Vec3 down = scene.gravity / g;
  const Vec3 wind = scene.air ? scene.air->wind : Vec3::Zero();
  StateForces forces(scene);
  State state = initial_state(scene);
  // The force on the body falling at s through the air, and its part against gravity.
  const auto force_at = [&](double s) {
    state[body].velocity = wind + s * down;
    return forces.at(state).force[body];
  };
  const auto holding = [&](double s) { return -force_at(s).dot(down); };
  const double weight = b.mass * g;
  double lo = 0.0, hi = 1.0;
  while (holding(hi) < weight) {
    lo = hi, hi *= 2.0;
    if (hi > 1e12) return fail(b.name + " has no drag (no force holds it against gravity)");
  }
  // Bisection to the last bit: the force grows with the speed.
  while (true) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (holding(mid) < weight ? lo : hi) = mid;
  }
  const double speed = holding(hi) - weight <= weight - holding(lo) ? hi : lo;
  const Vec3 f = force_at(speed);
  if ((f - f.dot(down) * down).norm() > 1e-9 * f.norm())
    return fail(b.name +
                " is pushed across its fall at its terminal speed (it spins and feels a "
                "Magnus force)");
  ForceJacobian jacobian;
  forces.model().jacobian(forces.view(state), jacobian);
  double along = 0.0;
  for (const JacobianBlock& block : jacobian.blocks())
    if (block.wrt == Wrt::Velocity && block.body == body && block.by_body == body)
      along += down.dot(block.value * down);
  return TerminalFall{speed, -along / b.mass};
}

}  // namespace bb
