// Springs in Bullet as its users build them: one btGeneric6DofSpring2Constraint per
// [[spring]] between the two bodies, its linear x axis along the spring with Bullet's own
// spring on it, every other axis free. Bullet's spring acts along its frame's x axis, which
// turns only with body a: set once, a spring would keep its starting direction and motion
// across it would stretch nothing (a rope falls through its own springs). So before each
// step the frames are aimed again along the line between the bodies' centres
// (btGeneric6DofSpring2Constraint::setFrames), as Box2D's distance joint takes its axis from
// the bodies at each step. What Bullet does to the stiffness it is given (limitIfNeeded) is
// worked out here by the engine's own rule and written into the run.
#pragma once

#include <BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.h>
#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

#include "model/world.hpp"
#include "seam/backend.hpp"
#include "seam/engine_tables.hpp"

namespace bb {

/// The stiffness and damping one spring row of btGeneric6DofSpring2Constraint applies.
struct SpringRow {
  double stiffness;  ///< N/m actually used
  double damping;    ///< N s/m actually used
  bool stiffness_limited;
  bool damping_limited;
};

/// Bullet 3.24's rule (btGeneric6DofSpring2Constraint.cpp, get_limit_motor_info2, lines
/// 836-860): with limitIfNeeded, a spring whose sqrt(k / m) dt exceeds 0.25 gets
/// k = m / (16 dt^2), and one whose c dt exceeds m gets c = m / dt, where m is the pair's
/// reduced mass, or the moving body's mass when the other is static (mass 0 here).
SpringRow bullet_spring_row(double stiffness, double damping, double mass_a, double mass_b,
                            double dt, bool limit_if_needed);

/// The scene's springs as constraints in `world`, removed again on destruction.
class BulletSpringJoints {
 public:
  BulletSpringJoints(const World& scene, const EngineTables& engines, double dt,
                     const std::vector<std::unique_ptr<btRigidBody>>& bodies,
                     btDynamicsWorld& world);
  ~BulletSpringJoints();
  BulletSpringJoints(const BulletSpringJoints&) = delete;
  BulletSpringJoints& operator=(const BulletSpringJoints&) = delete;

  /// Aims every spring's frames along the current line between its bodies' centres: called
  /// before each step. A spring whose bodies sit at one point keeps its last direction.
  void aim();

  /// How the springs are built and the stiffness and damping Bullet uses for them.
  void add_settings(Settings& out) const;

 private:
  btDynamicsWorld& world_;
  bool limit_if_needed_;
  std::vector<std::unique_ptr<btGeneric6DofSpring2Constraint>> joints_;
  std::vector<SpringRow> rows_;  ///< one per joint, as Bullet applies it
};

}  // namespace bb
