// The course text's collision handling, as pure functions on one contact: the floor rules
// of section 3 ("Three beachballs 1" and "1a") and the restitution blend of section 4
// ("Double bounce"). The course step calls them in its resolve phase.
#pragma once

#include <Eigen/Core>
#include <string>

#include "contact/contact_geometry.hpp"

namespace bb::course {

/// What a ball that is found below a fixed surface (the floor, a wall) does.
enum class GroundRule {
  Reflect,  ///< reverse the velocity only: the ball stays below and may sink (right ball)
  Clamp,    ///< reverse and move the ball out to touch the surface (left and middle balls)
  Mirror,   ///< reverse and move it out as far as it went in (1a's right ball)
};

/// How a ball that hits a moving box (a plank) is resolved, seed section 5.
enum class HitRule {
  SeedPlank,  ///< the seed's demo: the ball turns back, the plank takes its momentum too
  Impulse,    ///< Newton's restitution with rigid bodies (contact/rigid_hit.hpp)
};

/// The rule called `name` ("reflect", "clamp", "mirror"); throws std::invalid_argument.
GroundRule ground_rule(const std::string& name);
/// The rule called `name` ("seed-plank", "impulse"); throws std::invalid_argument.
HitRule hit_rule(const std::string& name);
std::string ground_rule_name(GroundRule rule);

/// Seed section 3: a body at `position` moving at `velocity` found at `p` (gap < 0) against
/// a fixed surface. The seed tests the height only, not the direction of motion: the normal
/// component of the velocity is reversed (scaled by `restitution`; the seed's balls use 1)
/// whenever the body is below, and the rule decides where the body is put.
void resolve_fixed(GroundRule rule, const contact::Proximity& p, double restitution,
                   Eigen::Vector3d& position, Eigen::Vector3d& velocity);

/// Seed section 4, the restitution blend (after Palmer): along the unit `normal` between
/// two bodies of masses m1 and m2, the normal velocities become
///   v1a = (v1b (m1 - e m2) + (1 + e) v2b m2) / (m1 + m2)
///   v2a = ((1 + e) v1b m1 + v2b (m2 - e m1)) / (m1 + m2),
/// plastic at e = 0, elastic at e = 1; the tangential velocities are kept.
void blend_collision(double m1, double m2, double restitution, const Eigen::Vector3d& normal,
                     Eigen::Vector3d& v1, Eigen::Vector3d& v2);

}  // namespace bb::course
