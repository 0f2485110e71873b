// One term of the force model: a force (and a torque about the centre) on some of the
// scene's bodies, from their state. Every term of a scene is evaluated once per evaluation
// of the forces and loops over its own bodies: no virtual call per body or per spring.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "model/world.hpp"
#include "physics/body_states.hpp"

namespace bb {

/// What a force's derivative is taken with respect to.
enum class Wrt { Position, Velocity, Spin };

/// d(force on `body`) / d(`wrt` of `by_body`): N/m, N s/m or N s; spins in the world frame.
struct JacobianBlock {
  int body = -1;
  int by_body = -1;
  Wrt wrt = Wrt::Velocity;
  Eigen::Matrix3d value = Eigen::Matrix3d::Zero();
};

/// The force model's derivatives as a list of 3x3 blocks (a body's own and a spring's
/// coupling of two bodies); blocks with the same place add up. Cleared and refilled at
/// each evaluation, it allocates nothing once it has held the most blocks.
class ForceJacobian {
 public:
  void clear() { blocks_.clear(); }
  void add(int body, int by_body, Wrt wrt, const Eigen::Matrix3d& value) {
    blocks_.push_back({body, by_body, wrt, value});
  }
  const std::vector<JacobianBlock>& blocks() const { return blocks_; }

 private:
  std::vector<JacobianBlock> blocks_;
};

/// Which forces a caller takes from the force model.
struct ForceOptions {
  /// False for an engine that builds the springs as its own joints.
  bool springs = true;
};

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  /// Adds this term's force (N, at the centre) and torque (N m, about the centre, world
  /// frame) on each body it acts on; `force` and `torque` have one entry per body.
  virtual void add(const BodyStates& s, Vec3* force, Vec3* torque) const = 0;
  /// Adds d(force)/d(state) where the term can give it (an implicit solver's Newton matrix);
  /// a term that leaves it out is treated as constant there. Torques give no derivative.
  /// The position blocks are the term's stiffness: the reference's choice of a stiff solver
  /// and the course's stability theory read them, so a term with a stiffness must give them.
  virtual void add_jacobian(const BodyStates&, ForceJacobian&) const {}
  /// Whether the term ever gives a torque (else callers skip turning the bodies by it).
  virtual bool torques() const { return false; }
  /// Potential energy (J) the term stores at `s`, for a term that has one (a spring's
  /// k (l - L)^2 / 2); 0 for one that has none (drag, a push), whose work supply() bounds.
  /// The scene's total energy adds it to the kinetic and gravitational energy.
  virtual double potential_energy(const BodyStates&) const { return 0.0; }
  /// Whether potential_energy() can be other than 0 (a caller with no such term skips it).
  virtual bool stores_energy() const { return false; }
  /// The most energy (J) the term can put into the bodies' motion over a run of `duration`
  /// seconds from the case's start `start`: for a term with a potential, what it stores there
  /// above its least; for a push or a wind, a bound on its work; 0 for a term that only takes
  /// energy (drag in still air, a keel). Divergence and stability are judged against it.
  virtual double supply(const BodyStates& /*start*/, double /*duration*/) const { return 0.0; }
};

/// Builds a term for `scene`, or nothing when the scene has no use for it.
using ForceTermFactory = std::unique_ptr<ForceTerm> (*)(const World& scene,
                                                        const ForceOptions& options);

}  // namespace bb
