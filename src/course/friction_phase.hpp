// The friction phase of the course step (seed section 6): which bodies touch a ground with
// friction at the start of a step, the friction force inside the integrator's force
// evaluations, and the `clamp` rule's zero-crossing check after the step. Buffers are sized
// once, so a step allocates nothing.
#pragma once

#include <vector>

#include "course/friction_rules.hpp"
#include "scene/contact_pairs.hpp"
#include "scene/scene.hpp"

namespace bb::course {

class FrictionPhase {
 public:
  /// `dt` is the step, which `low-speed` needs; throws UnsupportedScene when a [[contact]]
  /// between bodies has friction (the course's rules act against the ground only).
  FrictionPhase(const Scene& scene, FrictionRule rule, double dt);
  /// No body can touch a ground with friction: the phase does nothing.
  bool empty() const { return bodies_.empty(); }
  /// Before the step: which bodies touch the ground (a gap of at most kTouching), and
  /// their velocities, for the clamp rule.
  void begin(const std::vector<Vec3>& x, const std::vector<Quat>& q, const std::vector<Vec3>& v);
  /// In each force evaluation: a touching body's acceleration with the ground's friction.
  void apply(const std::vector<Vec3>& v, std::vector<Vec3>& a) const;
  /// After the step (and the ground rule): the clamp rule's zero crossing.
  void end(std::vector<Vec3>& v) const;

  /// A body this close to the ground (metres) touches it: the ground rules leave a body on
  /// the ground at a gap of rounding size.
  static constexpr double kTouching = 1e-9;

 private:
  const Scene& scene_;
  FrictionRule rule_;
  double dt_;
  Eigen::Vector3d normal_ = Eigen::Vector3d::UnitY();
  std::vector<ContactPair> pairs_;  ///< each body's pair with the ground
  std::vector<Coulomb> coulomb_;    ///< its coefficients
  std::vector<int> bodies_;         ///< the bodies that can touch it
  std::vector<char> touching_;      ///< per entry of bodies_, at the step's start
  std::vector<Vec3> before_;        ///< per entry of bodies_: the velocity at the step's start
};

}  // namespace bb::course
