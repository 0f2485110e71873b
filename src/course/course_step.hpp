// The course step as named phases, the way Box2D and MuJoCo lay theirs out: forces,
// integrate, detect, resolve, friction. A course variant is a choice per phase: the
// integrator (seed section 1), the ground rule (section 3) and the friction rule (section 6,
// friction_phase.hpp). Between bodies the seed's restitution blend (section 4) always
// applies.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "contact/contact_pairs.hpp"
#include "course/collision_rules.hpp"
#include "course/friction_rules.hpp"
#include "course/integrators.hpp"
#include "scene/scene.hpp"

namespace bb::course {

/// The choice a variant makes in each phase.
struct Phases {
  StepFn integrate = nullptr;                   ///< forces are evaluated inside, at its stages
  GroundRule ground = GroundRule::Mirror;       ///< against the ground and fixed bodies
  FrictionRule friction = FrictionRule::Clamp;  ///< against a ground with friction
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
  ContactPhases(const Scene& scene, GroundRule rule);
  /// Detect: every pair whose gap is below zero at positions `x` and orientations `q`.
  void detect(const std::vector<Vec3>& x, const std::vector<Quat>& q);
  /// Resolve: each found contact by the ground rule (ground, fixed bodies) or the
  /// restitution blend (two moving bodies, only while they approach).
  void resolve(std::vector<Vec3>& x, std::vector<Vec3>& v);
  const std::vector<FoundContact>& found() const { return found_; }
  bool empty() const { return pairs_.empty(); }

 private:
  const Scene& scene_;
  GroundRule rule_;
  std::vector<ContactPair> pairs_;
  std::vector<FoundContact> found_;
};

}  // namespace bb::course
