// The plank on an axis (seed section 5) as a course method: a body on a [[hinge]] keeps
// its angular momentum about the axis, L += T dt with T the torque of the forces at its
// centre (and an impulse's moment at once), turns by omega = L / J, and its centre is
// carried round the anchor. J is the seed's: a plank (a box, its longest side the
// length) split at the axis into two rods, 1/3 m d1^2 + 1/3 m d2^2 (plank_inertia.hpp);
// another shape gets its true inertia about the axis. A hinged box that touches the ground
// (the falling wall of section 8, on its bottom edge) cannot turn into it: a step that would
// put a corner below the ground is not taken, and the spin is reversed and scaled by the
// restitution, the clamp rule of section 3 applied to the angle.
#pragma once

#include <vector>

#include "model/world.hpp"

namespace bb::course {

class HingeTurning {
 public:
  /// Sets up every hinged body of `scene` at its starting state.
  explicit HingeTurning(const World& scene);
  bool empty() const { return hinges_.empty(); }
  /// The seed's J (kg m^2) of hinge k's body about its axis.
  double inertia(std::size_t k) const { return inertia_[k]; }
  /// One step of `dt` seconds from the positions `x` and orientations `q` of the step's
  /// start, under accelerations `a` (m/s^2, from the forces at the centres): each hinged
  /// body's position, velocity, orientation and spin are set.
  void step(double dt, const std::vector<Vec3>& a, std::vector<Vec3>& x, std::vector<Vec3>& v,
            std::vector<Quat>& q, std::vector<Vec3>& spin);
  /// An impulse on a hinged body: its moment about the axis adds to L at once. False when
  /// the body is on no hinge.
  bool push(const Impulse& impulse, std::vector<Vec3>& x, std::vector<Vec3>& v,
            std::vector<Vec3>& spin);

 private:
  /// Whether body i, turned from (x0, q0) to (x1, q1) about `h`, went further below the
  /// ground than it was.
  bool into_ground(int i, const Hinge& h, const Vec3& x0, const Quat& q0, const Vec3& x1,
                   const Quat& q1) const;

  const World& scene_;
  std::vector<const Hinge*> hinges_;
  std::vector<double> inertia_;   ///< the seed's J per hinge
  std::vector<double> momentum_;  ///< L about the axis per hinge, N m s
  /// Per hinge: the restitution of its body's ground contact, or -1 when it has none.
  std::vector<double> ground_restitution_;
};

}  // namespace bb::course
