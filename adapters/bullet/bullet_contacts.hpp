// Contacts in Bullet, set up the way a user of the engine does: its own shapes and
// collision detection, a pair filter on the broadphase so that only the pairs the case
// lists can touch, and a contact-added callback that gives every contact point its pair's
// restitution and friction instead of Bullet's product of the two bodies' values.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

#include "scene/scene.hpp"

namespace bb {

/// Whether the scene has anything to touch: a ground or a [[contact]].
bool scene_has_contacts(const Scene& scene);

/// How one pair of collision objects touches.
struct PairMaterial {
  bool touches = false;
  btScalar restitution = 0;
  btScalar friction = 0;  ///< Bullet's one Coulomb coefficient: the case's friction_kinetic
};

/// Every pair that can touch, from contact_pairs(scene). Collision objects are numbered by
/// their user index: the scene's bodies in order, then the ground. Point bodies touch nothing.
class PairTable {
 public:
  explicit PairTable(const Scene& scene);
  const PairMaterial& at(int a, int b) const;
  int ground_index() const { return count_ - 1; }

 private:
  int count_;  ///< bodies and the ground
  std::vector<PairMaterial> cells_;
};

/// Lets the broadphase pair only objects that the table says touch (replaces Bullet's
/// collision group and mask test).
class PairFilter : public btOverlapFilterCallback {
 public:
  explicit PairFilter(const PairTable& table) : table_(table) {}
  bool needBroadphaseCollision(btBroadphaseProxy* proxy0, btBroadphaseProxy* proxy1) const override;

 private:
  const PairTable& table_;
};

/// Sets gContactAddedCallback, once per loaded library, to a function that gives each new
/// or refreshed contact point its pair's restitution and friction. It acts on objects with
/// CF_CUSTOM_MATERIAL_CALLBACK whose user pointer is their simulation's PairTable.
void install_pair_material_callback();

/// The collision shape of a sphere or box body; nullptr for a point body.
std::unique_ptr<btCollisionShape> make_shape(const Body& body);

/// The ground as Bullet's infinite static plane: n . x = n . point.
std::unique_ptr<btCollisionShape> make_ground_shape(const Ground& ground);

}  // namespace bb
