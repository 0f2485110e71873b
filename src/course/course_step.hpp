// The course step as named phases, the way Box2D and MuJoCo lay theirs out: forces,
// integrate, detect, resolve, friction. A course variant is a choice per phase: the
// integrator (seed section 1), the ground rule (section 3), the friction rule (section 6,
// friction_phase.hpp), the rule for a ball hitting a moving box and the spin rule (section
// 5). Between two balls the seed's restitution blend (section 4) always applies.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "contact/contact_pairs.hpp"
#include "course/collision_rules.hpp"
#include "course/friction_rules.hpp"
#include "course/integrators.hpp"
#include "course/kinematic_spin.hpp"
#include "model/world.hpp"

namespace bb::course {

/// The choice a variant makes in each phase.
struct Phases {
  StepFn integrate = nullptr;                   ///< forces are evaluated inside, at its stages
  GroundRule ground = GroundRule::Mirror;       ///< against the ground and fixed bodies
  FrictionRule friction = FrictionRule::Clamp;  ///< against a ground with friction
  HitRule hit = HitRule::SeedPlank;             ///< a ball against a moving box
  SpinRule spin = SpinRule::Free;               ///< a ball's spin at its contacts
};

/// A contact found in the detect phase: the pair and where it stands.
struct FoundContact {
  std::size_t pair = 0;  ///< index into the scene's contact pairs
  contact::Proximity proximity;
};

/// The detect and resolve phases over a scene's contact pairs; buffers are sized once, so
/// a step allocates nothing.
class ContactPhases {
 public:
  /// `dt` is the step, for the spin rule's per-step reading of a spin.
  ContactPhases(const World& scene, const Phases& phases, double dt);
  /// Detect: every pair whose gap is below zero at positions `x` and orientations `q`.
  void detect(const std::vector<Vec3>& x, const std::vector<Quat>& q);
  /// Resolve: each found contact by the ground rule (ground, fixed bodies), the hit rule
  /// (a ball against a moving box) or the restitution blend (two balls), the last two only
  /// while the bodies approach; then the spin rule sets the balls' spins `w`.
  void resolve(std::vector<Vec3>& x, std::vector<Vec3>& v, const std::vector<Quat>& q,
               std::vector<Vec3>& w);
  const std::vector<FoundContact>& found() const { return found_; }
  const ContactPair& pair(std::size_t k) const { return pairs_[k]; }
  bool empty() const { return pairs_.empty(); }

 private:
  /// The hit rule between ball a and moving box b of `pair`.
  void hit(const ContactPair& pair, const contact::Proximity& p, const std::vector<Vec3>& x,
           std::vector<Vec3>& v, const std::vector<Quat>& q, std::vector<Vec3>& w) const;

  const World& scene_;
  Phases phases_;
  double dt_;
  std::vector<ContactPair> pairs_;
  std::vector<FoundContact> found_;
};

}  // namespace bb::course
