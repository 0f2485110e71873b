// Hinges in Bullet as its users build them: one btHingeConstraint per [[hinge]] between
// the body and the world (Bullet's fixed body), pivot and axis in the body's own frame.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

#include "model/world.hpp"
#include "seam/backend.hpp"

namespace bb {

/// The scene's hinges as constraints in `world`, removed again on destruction.
class BulletHingeJoints {
 public:
  BulletHingeJoints(const World& scene, const std::vector<std::unique_ptr<btRigidBody>>& bodies,
                    btDynamicsWorld& world);
  ~BulletHingeJoints();
  BulletHingeJoints(const BulletHingeJoints&) = delete;
  BulletHingeJoints& operator=(const BulletHingeJoints&) = delete;

  /// How the hinges are built and what their rows are solved with.
  void add_settings(Settings& out) const;

 private:
  btDynamicsWorld& world_;
  std::vector<std::unique_ptr<btHingeConstraint>> joints_;
};

}  // namespace bb
