// The friction phase of the course step (seed section 6): which bodies are in contact with
// a ground with friction at the start of a step, the friction force inside the integrator's
// force evaluations, and the `clamp` rule's stop. Buffers are sized once, so a step
// allocates nothing.
//
// In contact, whatever the ground rule (a rule that lifts a body out, as mirror does, must
// not switch friction off): touching or overlapping the ground at the step's start (a gap
// of at most kTouching), or in contact in the step before or resolved against the ground in
// it, and not leaving it: under its normal velocity and gravity's pull into the ground
// alone it would be back on the ground within four steps (gap + v_n T - g_n T^2 / 2 at most
// kTouching, T = 4 dt). The ground rules keep a body at rest hopping by the step's scale:
// mirror lifts a block out by as much as it sank, up to 2 g_n dt^2, a hop of four steps;
// a bounce that leaves for longer is a flight, and friction waits for the landing.
#pragma once

#include <vector>

#include "course/friction_rules.hpp"
#include "model/contact_pairs.hpp"
#include "model/world.hpp"

namespace bb::course {

class FrictionPhase {
 public:
  /// `dt` is the step, which `low-speed` needs; throws UnsupportedScene when a [[contact]]
  /// between bodies has friction (the course's rules act against the ground only).
  FrictionPhase(const World& scene, FrictionRule rule, double dt);
  /// No body can touch a ground with friction: the phase does nothing.
  bool empty() const { return bodies_.empty(); }
  /// Before the step: which bodies are in contact with the ground (above), and their
  /// velocities, for the clamp rule.
  void begin(const std::vector<Vec3>& x, const std::vector<Quat>& q, const std::vector<Vec3>& v);
  /// Whether the clamp rule needs the accelerations at the step's start (stop_slides).
  bool stops_slides() const;
  /// Before the step, the clamp rule's stop: a body in contact whose slide the step would
  /// turn back (its speed along the ground at most what kinetic friction, less the other
  /// forces' pull along its slide, takes off over the step, from the accelerations `a` the
  /// other forces give at the step's start) stops now: its velocity along the ground
  /// becomes zero, and static friction decides the step from rest. Every integrator: Verlet
  /// and RK4 approach zero without crossing it within a step, so a check after the step
  /// alone never fires for them.
  void stop_slides(const std::vector<Vec3>& a, std::vector<Vec3>& v);
  /// After the step's resolve phase: body `body` was resolved against the ground.
  void resolved(int body);
  /// In each force evaluation: a touching body's acceleration with the ground's friction.
  void apply(const std::vector<Vec3>& v, std::vector<Vec3>& a) const;
  /// After the step (and the ground rule): the clamp rule's zero crossing, for what the
  /// stop before the step did not foresee (forces that change within the step).
  void end(std::vector<Vec3>& v);

  /// A body this close to the ground (metres) touches it: the ground rules leave a body on
  /// the ground at a gap of rounding size.
  static constexpr double kTouching = 1e-9;

 private:
  const World& scene_;
  FrictionRule rule_;
  double dt_;
  Eigen::Vector3d normal_ = Eigen::Vector3d::UnitY();
  std::vector<ContactPair> pairs_;  ///< each body's pair with the ground
  std::vector<Coulomb> coulomb_;    ///< its coefficients
  std::vector<int> bodies_;         ///< the bodies that can touch it
  std::vector<char> touching_;      ///< per entry of bodies_: in contact this step
  std::vector<char> resolved_;      ///< per entry of bodies_: resolved in this step
  std::vector<int> entry_;          ///< per body: its entry in bodies_, or -1
  std::vector<Vec3> before_;        ///< per entry of bodies_: the velocity at the step's start
  double pull_ = 0.0;               ///< m/s^2: gravity's part into the ground
};

}  // namespace bb::course
