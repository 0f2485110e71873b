// The one friction coefficient every engine adapter gives a pair, and why. Bullet, Box2D
// and ODE each have a single Coulomb coefficient for sticking and sliding alike, where a
// case gives two (friction_static and friction_kinetic); each adapter takes it from here.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "model/contact_pairs.hpp"
#include "model/world.hpp"
#include "seam/backend.hpp"

namespace bb {

/// The coefficient an engine gets for `pair`: the case's friction_kinetic. The sliding
/// cases measure what kinetic friction decides (a box sliding from v0 stops after
/// v0^2 / (2 mu_k g)); the price is paid by a body at rest, which the engine holds only up to
/// the slope atan(mu_k) instead of atan(mu_s): between the two it slides, at
/// g (sin a - mu_k cos a), where Coulomb's static friction would hold it.
inline double engine_friction(const ContactPair& pair) {
  return pair.friction_kinetic;
}

/// Appends "friction_rule" (which coefficient, and what follows) and, when some body can
/// touch the ground, "ground_friction_min" and "ground_friction_max": the least and the
/// greatest coefficient a body's contact with the ground gets (a [[contact]] naming a body
/// and "ground" may give it its own).
inline void add_friction_settings(const World& scene, Settings& settings) {
  settings.push_back(
      {"friction_rule",
       std::string("one Coulomb coefficient per contact, for sticking and sliding alike: the "
                   "pair's friction_kinetic, so that a slide stops after v0^2 / (2 mu_k g); a "
                   "body at rest is then held only on slopes below atan(mu_k), not "
                   "atan(mu_s), and slides between the two; friction_static is not used")});
  std::vector<double> ground;
  for (const ContactPair& pair : contact_pairs(scene))
    if (pair.ground()) ground.push_back(engine_friction(pair));
  if (ground.empty()) return;
  const auto [lo, hi] = std::minmax_element(ground.begin(), ground.end());
  settings.push_back({"ground_friction_min", *lo});
  settings.push_back({"ground_friction_max", *hi});
}

}  // namespace bb
