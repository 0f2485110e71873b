#include "bullet_contacts.hpp"

#include <algorithm>

#include "../engine_friction.hpp"
#include "bullet_vectors.hpp"
#include "model/contact_pairs.hpp"

namespace bb {

namespace {

/// Bullet calls this for every contact point it adds or refreshes between objects of
/// which one has CF_CUSTOM_MATERIAL_CALLBACK (btManifoldResult::addContactPoint).
bool set_pair_material(btManifoldPoint& point, const btCollisionObjectWrapper* wrap0, int, int,
                       const btCollisionObjectWrapper* wrap1, int, int) {
  const btCollisionObject* a = wrap0->getCollisionObject();
  const btCollisionObject* b = wrap1->getCollisionObject();
  const auto* table = static_cast<const PairTable*>(a->getUserPointer());
  if (table == nullptr) table = static_cast<const PairTable*>(b->getUserPointer());
  if (table == nullptr) return false;
  const PairMaterial& m = table->at(a->getUserIndex(), b->getUserIndex());
  point.m_combinedRestitution = m.restitution;
  point.m_combinedFriction = m.friction;
  return true;
}

}  // namespace

bool scene_has_contacts(const World& scene) {
  return scene.ground.has_value() || !scene.contacts.empty();
}

PairTable::PairTable(const World& scene)
    : count_(static_cast<int>(scene.bodies.size()) + 1),
      cells_(static_cast<std::size_t>(count_ * count_)) {
  for (const ContactPair& pair : contact_pairs(scene)) {
    const int a = pair.a;
    const int b = pair.ground() ? ground_index() : pair.b;
    // A point body never collides (point_body.hpp).
    const bool point = scene.bodies[a].shape == Shape::Point ||
                       (!pair.ground() && scene.bodies[b].shape == Shape::Point);
    if (point) continue;
    const PairMaterial m{true, btScalar(pair.restitution), btScalar(engine_friction(pair))};
    cells_[static_cast<std::size_t>(a * count_ + b)] = m;
    cells_[static_cast<std::size_t>(b * count_ + a)] = m;
  }
}

const PairMaterial& PairTable::at(int a, int b) const {
  static const PairMaterial none;
  if (a < 0 || b < 0 || a >= count_ || b >= count_) return none;
  return cells_[static_cast<std::size_t>(a * count_ + b)];
}

bool PairFilter::needBroadphaseCollision(btBroadphaseProxy* proxy0,
                                         btBroadphaseProxy* proxy1) const {
  const auto* a = static_cast<const btCollisionObject*>(proxy0->m_clientObject);
  const auto* b = static_cast<const btCollisionObject*>(proxy1->m_clientObject);
  return table_.at(a->getUserIndex(), b->getUserIndex()).touches;
}

void install_pair_material_callback() {
  // A thread-safe one-time store: runs may start in parallel threads of one process.
  static const bool installed = [] {
    gContactAddedCallback = &set_pair_material;
    return true;
  }();
  (void)installed;
}

std::unique_ptr<btCollisionShape> make_shape(const Body& body) {
  switch (body.shape) {
    case Shape::Sphere:
      // A sphere's collision margin is its radius (btSphereShape).
      return std::make_unique<btSphereShape>(btScalar(body.radius));
    case Shape::Box:
      // Bullet's default margin, 0.04 m, lowered to a tenth of the smallest half extent
      // for thin boxes (btBoxShape's setSafeMargin); the faces stay at the half extents.
      return std::make_unique<btBoxShape>(to_bt(body.half_extents));
    case Shape::Point:
      break;
  }
  return nullptr;
}

std::unique_ptr<btCollisionShape> make_ground_shape(const Ground& ground) {
  return std::make_unique<btStaticPlaneShape>(to_bt(ground.normal),
                                              btScalar(ground.normal.dot(ground.point)));
}

PlaneMultipoint plane_multipoint(const World& scene) {
  const bool box_on_ground =
      scene.ground && std::any_of(scene.bodies.begin(), scene.bodies.end(),
                                  [](const Body& b) { return b.shape == Shape::Box && !b.fixed; });
  return box_on_ground ? PlaneMultipoint{6, 5} : PlaneMultipoint{};
}

}  // namespace bb
