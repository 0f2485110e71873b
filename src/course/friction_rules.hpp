// The course text's friction, section 6: Coulomb's law with a static and a kinetic
// coefficient, and the three ways a discrete step can apply it to a body on the ground:
// `naive` (the "sliding block" demo as first written: the force opposes the velocity, so
// the block overshoots zero and crawls), and the seed's two fixes, `clamp` (a velocity
// that would cross zero within a step is set to zero) and `low-speed` (the friction is
// reduced at low speed so that one step cannot reverse the velocity). The seed's check is
// made before the step here (stops_within): a slide the step would turn back stops, which
// holds for every integrator, not only those whose velocity crosses zero within a step.
#pragma once

#include <Eigen/Core>
#include <string>

namespace bb::course {

enum class FrictionRule { Naive, Clamp, LowSpeed };

/// The rule called `name` ("naive", "clamp", "low-speed"); throws std::invalid_argument.
FrictionRule friction_rule(const std::string& name);
std::string friction_rule_name(FrictionRule rule);

/// A tangential speed below this (m/s) is rounding, not sliding: the body is at rest.
inline constexpr double kRestSpeed = 1e-12;

/// The coefficients of one body's contact with the ground.
struct Coulomb {
  double mu_static = 0.0;
  double mu_kinetic = 0.0;
};

/// The acceleration of a body touching the ground (unit normal `n`) moving at `v`, whose
/// other forces give it `a`, once the ground's friction acts on it:
/// - pressed onto the ground with N / m = -a.n > 0 (not pressed: `a` unchanged);
/// - sliding (|v_t| > kRestSpeed): kinetic friction mu_k N against the tangential velocity;
///   `low-speed` caps it at m |v_t| / dt, the force that stops the body in one step of `dt`;
/// - at rest: static friction cancels the tangential force up to mu_s N; beyond that the
///   body breaks away and kinetic friction mu_k N opposes the tangential force.
Eigen::Vector3d with_friction(FrictionRule rule, const Coulomb& c, const Eigen::Vector3d& n,
                              const Eigen::Vector3d& v, const Eigen::Vector3d& a, double dt);

/// The `clamp` rule's stop, before a step of `dt`: whether a body sliding at `v` on the
/// plane with unit normal `n`, whose other forces give it `a`, would have its slide turned
/// back within the step: pressed on the ground (N / m = -a.n > 0) and sliding, its speed
/// along the ground is at most what kinetic friction less the other forces' pull along the
/// slide take off over the step, (mu_k N / m - a . v_t / |v_t|) dt.
bool stops_within(const Coulomb& c, const Eigen::Vector3d& n, const Eigen::Vector3d& v,
                  const Eigen::Vector3d& a, double dt);

/// After a step, the `clamp` rule: a tangential velocity that turned against the one before
/// the step (`before`) crossed zero within the step, and is set to zero. Other rules, and
/// velocities that did not turn, are left alone.
void clamp_reversal(FrictionRule rule, const Eigen::Vector3d& n, const Eigen::Vector3d& before,
                    Eigen::Vector3d& v);

/// The part of `v` along the plane with unit normal `n`.
inline Eigen::Vector3d tangential(const Eigen::Vector3d& v, const Eigen::Vector3d& n) {
  return v - v.dot(n) * n;
}

}  // namespace bb::course
