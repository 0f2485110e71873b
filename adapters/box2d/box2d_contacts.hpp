// Box2D's side of a scene's contacts: a fixture for each sphere and box that can touch
// something, a static box along the ground line, a filter that lets only the case's pairs
// collide, and a listener that gives every contact the case's restitution and friction in
// place of Box2D's mixing rules. Built only for a scene with contacts.
#pragma once

#include <box2d/box2d.h>

#include <vector>

#include "model/contact_pairs.hpp"
#include "model/world.hpp"
#include "seam/backend.hpp"

namespace bb {

/// Half the length of the ground box along the ground line, metres. Only its top face
/// matters and that face's midpoint is the ground's point, so the length costs no precision.
inline constexpr float kGroundHalfLength = 1000.0f;
/// Half the ground box's thickness below the line, metres.
inline constexpr float kGroundHalfDepth = 1.0f;

class Box2dContacts : public b2ContactFilter, public b2ContactListener {
 public:
  /// Adds the fixtures (and the ground body) to `world`; `bodies` are the scene's bodies
  /// in order. Fixtures carry no mass: the caller sets mass and inertia afterwards.
  Box2dContacts(const World& scene, b2World& world, const std::vector<b2Body*>& bodies,
                float restitution_threshold);

  /// Only pairs that contact_pairs() lists may collide.
  bool ShouldCollide(b2Fixture* fixture_a, b2Fixture* fixture_b) override;
  /// The case's restitution and friction for this pair, set before every solve.
  void PreSolve(b2Contact* contact, const b2Manifold* old_manifold) override;

  /// Contacts so far that began approaching slower than the restitution threshold, with a
  /// restitution above zero: bounces the case has and Box2D does not make.
  int bounces_below_threshold() const { return bounces_below_threshold_; }

 private:
  /// The pair two fixtures stand for, or nullptr when the case lists none.
  const ContactPair* pair_of(b2Fixture* a, b2Fixture* b) const;
  /// Index into pairs_ for two slots (a body's index, or slots_ - 1 for the ground).
  int& table(std::size_t a, std::size_t b) { return table_[a * slots_ + b]; }

  std::vector<ContactPair> pairs_;
  float restitution_threshold_ = 1.0f;
  int bounces_below_threshold_ = 0;
  std::size_t slots_ = 0;   ///< bodies + 1 (the ground)
  std::vector<int> table_;  ///< slots_ x slots_, symmetric; -1: may not touch
};

/// The engine_settings entries that describe how contacts work in Box2D and in this adapter,
/// with what `contacts` saw during the run.
void add_contact_settings(const World& scene, const Box2dContacts& contacts, Settings& settings);

}  // namespace bb
