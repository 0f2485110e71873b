#include "box2d_contacts.hpp"

#include <cmath>
#include <string>

#include "../engine_friction.hpp"
#include "box2d_vectors.hpp"

namespace bb {

namespace {

/// A fixture's slot (GetUserData is not const in 2.4.1): its body's index, or the
/// ground's, kept in its user data plus one
/// (zero is Box2D's "no data").
std::size_t slot_of(b2Fixture* fixture) {
  return static_cast<std::size_t>(fixture->GetUserData().pointer - 1);
}

b2FixtureDef fixture_def(const b2Shape* shape, std::size_t slot, float restitution_threshold) {
  b2FixtureDef def;
  def.shape = shape;
  // No mass from the shape (the adapter sets the case's), no friction or restitution of
  // its own (PreSolve sets the pair's).
  def.density = 0.0f;
  def.friction = 0.0f;
  def.restitution = 0.0f;
  def.restitutionThreshold = restitution_threshold;
  def.userData.pointer = slot + 1;
  return def;
}

}  // namespace

Box2dContacts::Box2dContacts(const World& scene, b2World& world, const std::vector<b2Body*>& bodies,
                             float restitution_threshold)
    : pairs_(contact_pairs(scene)),
      restitution_threshold_(restitution_threshold),
      slots_(scene.bodies.size() + 1),
      table_(slots_ * slots_, -1) {
  const std::size_t ground = slots_ - 1;
  std::vector<bool> touches(slots_, false);
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const std::size_t a = static_cast<std::size_t>(pairs_[i].a);
    const std::size_t b = pairs_[i].ground() ? ground : static_cast<std::size_t>(pairs_[i].b);
    table(a, b) = table(b, a) = static_cast<int>(i);
    touches[a] = touches[b] = true;
  }
  // A circle per sphere, a box per box; a point body never collides (point_body.hpp).
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& body = scene.bodies[i];
    if (!touches[i] || body.shape == Shape::Point) continue;
    b2CircleShape circle;
    b2PolygonShape box;
    const b2Shape* shape = &circle;
    if (body.shape == Shape::Sphere) {
      circle.m_radius = float(body.radius);
    } else {
      box.SetAsBox(float(body.half_extents.x()), float(body.half_extents.y()));
      shape = &box;
    }
    const b2FixtureDef def = fixture_def(shape, i, restitution_threshold);
    bodies[i]->CreateFixture(&def);
  }
  // The ground: a static box whose top face lies on the ground line, its midpoint at the
  // ground's point, turned so that the face's normal is the ground's.
  if (scene.ground) {
    b2BodyDef def;
    def.type = b2_staticBody;
    def.position = to_b2(scene.ground->point);
    def.angle = float(std::atan2(-scene.ground->normal.x(), scene.ground->normal.y()));
    b2Body* body = world.CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox(kGroundHalfLength, kGroundHalfDepth, b2Vec2(0.0f, -kGroundHalfDepth), 0.0f);
    const b2FixtureDef fixture = fixture_def(&box, ground, restitution_threshold);
    body->CreateFixture(&fixture);
  }
  world.SetContactFilter(this);
  world.SetContactListener(this);
}

const ContactPair* Box2dContacts::pair_of(b2Fixture* a, b2Fixture* b) const {
  const int i = table_[slot_of(a) * slots_ + slot_of(b)];
  return i < 0 ? nullptr : &pairs_[static_cast<std::size_t>(i)];
}

bool Box2dContacts::ShouldCollide(b2Fixture* fixture_a, b2Fixture* fixture_b) {
  return pair_of(fixture_a, fixture_b) != nullptr;
}

void Box2dContacts::PreSolve(b2Contact* contact, const b2Manifold* old_manifold) {
  const ContactPair* pair = pair_of(contact->GetFixtureA(), contact->GetFixtureB());
  if (pair == nullptr) return;
  contact->SetRestitution(float(pair->restitution));
  // Box2D has one friction coefficient for sticking and sliding (engine_friction.hpp).
  contact->SetFriction(float(engine_friction(*pair)));
  // A contact that has just begun: would the solver bounce it? Its approach speed at the
  // first point, as the contact solver measures it (b2ContactSolver's vRel).
  if (old_manifold->pointCount > 0 || pair->restitution <= 0.0) return;
  b2WorldManifold world;
  contact->GetWorldManifold(&world);
  const b2Vec2 point = world.points[0];
  const b2Vec2 relative =
      contact->GetFixtureB()->GetBody()->GetLinearVelocityFromWorldPoint(point) -
      contact->GetFixtureA()->GetBody()->GetLinearVelocityFromWorldPoint(point);
  const float approach = -b2Dot(world.normal, relative);
  if (approach > 0.0f && approach < restitution_threshold_) ++bounces_below_threshold_;
}

void add_contact_settings(const World& scene, const Box2dContacts& contacts, Settings& s) {
  s.push_back(
      {"collision", std::string("Box2D's own detection: a b2CircleShape per sphere and a "
                                "b2PolygonShape box per box that some pair lists; fixed bodies "
                                "static; only contact_pairs() may collide (b2ContactFilter)")});
  if (scene.ground)
    s.push_back({"ground", std::string("static box 2000 m x 2 m whose top face is the "
                                       "ground line, turned to the ground's normal")});
  s.push_back({"restitution_rule",
               std::string("Box2D mixes a contact's restitution as max(eA, eB) "
                           "(b2MixRestitution) and friction as sqrt(muA muB) (b2MixFriction); "
                           "the adapter sets every contact's restitution and friction to the "
                           "case's pair value in b2ContactListener::PreSolve, before each "
                           "solve")});
  add_friction_settings(scene, s);
  s.push_back({"friction_model",
               std::string("one tangent row per contact point (2D: along the contact line), "
                           "bounded by mu x that point's accumulated normal impulse, solved "
                           "before the normal rows in each velocity iteration "
                           "(b2ContactSolver::SolveVelocityConstraints)")});
  s.push_back({"restitution_threshold_rule",
               std::string("a contact whose normal approach speed is below "
                           "restitution_threshold m/s does not bounce (b2ContactSolver: "
                           "restitution only when vRel < -threshold), whatever the case's "
                           "restitution; bounces_below_threshold counts this run's contacts "
                           "that began so slowly with a restitution above zero")});
  s.push_back({"bounces_below_threshold", double(contacts.bounces_below_threshold())});
  s.push_back({"linear_slop", std::string("0.005 m (b2_linearSlop, compile-time): the "
                                          "position solver leaves this much overlap")});
  s.push_back(
      {"polygon_skin",
       std::string("0.01 m (b2_polygonRadius, compile-time): boxes and the ground box are "
                   "rounded by it, so a sphere touches them 1 cm before their surfaces meet and "
                   "rests about 5 mm above, and a box rests on its skin and the ground's, not "
                   "on its face: its face about 2 cm less the 5 mm of linear slop above the "
                   "ground (a box placed on the ground is pushed up to there)")});
  s.push_back({"polygon_skin_m", double(b2_polygonRadius)});
  s.push_back({"position_correction",
               std::string("Baumgarte 0.2 (b2_baumgarte; 0.75 in time-of-impact steps), at "
                           "most 0.2 m per step (b2_maxLinearCorrection), compile-time")});
  s.push_back({"continuous_collision",
               std::string("always between a moving body and a static one; between two "
                           "moving bodies only when one is a bullet (bullet key)")});
}

}  // namespace bb
