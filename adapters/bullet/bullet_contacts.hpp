// Contacts in Bullet, set up the way a user of the engine does: its own shapes and
// collision detection, a pair filter on the broadphase so that only the pairs the case
// lists can touch, and a contact-added callback that gives every contact point its pair's
// restitution and friction instead of Bullet's product of the two bodies' values.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

#include "model/world.hpp"

namespace bb {

/// Whether the scene has anything to touch: a ground or a [[contact]].
bool scene_has_contacts(const World& scene);

/// How one pair of collision objects touches.
struct PairMaterial {
  bool touches = false;
  btScalar restitution = 0;
  btScalar friction = 0;  ///< Bullet's one Coulomb coefficient: engine_friction()
};

/// Every pair that can touch, from contact_pairs(scene). Collision objects are numbered by
/// their user index: the scene's bodies in order, then the ground. Point bodies touch nothing.
class PairTable {
 public:
  explicit PairTable(const World& scene);
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

/// The arguments of btDefaultCollisionConfiguration::setPlaneConvexMultipointIterations.
/// Without them a box on btStaticPlaneShape gets one contact point per step (its deepest
/// vertex, btConvexPlaneCollisionAlgorithm) and builds its manifold over the following
/// steps: it rocks on one corner and sinks. With them, while the manifold holds fewer than
/// `threshold` points, `iterations` more queries with the box tilted slightly about axes in
/// the plane, spread evenly around the normal, add the corners those tilts make deepest.
/// Box-box pairs need none (btBoxBoxCollisionAlgorithm clips faces); spheres never get them
/// (Bullet's source: they would roll on the extra off-centre points).
struct PlaneMultipoint {
  int iterations = 1;  ///< Bullet's default; with threshold 0 no extra query is ever made
  int threshold = 0;
};

/// 6 and 5 when a moving box can touch the ground; Bullet's own default, off, otherwise.
/// Not the 3 and 3 that Bullet's header suggests, measured on a 1 m box sliding at 5 m/s
/// (mu 0.5, 1/60 s): the threshold is checked against last step's points before the slide
/// has carried them off (8 cm a step), so at 3 the box stood on one point in 26 of 180
/// steps, bobbed, sank 7.6 mm and stopped after 2.470 m; and 3 tilts 120 degrees apart can
/// miss a corner. A threshold of 5, above the manifold's 4 points, queries every step; 6
/// tilts 60 degrees apart always find all four corners of a face (each corner is deepest
/// over a 90 degree sector of tilt directions), whatever the box's yaw: 4 points every
/// step, no sinking, 2.5068 m, as Box2D and ODE.
PlaneMultipoint plane_multipoint(const World& scene);

}  // namespace bb
