// Which things in a scene can touch, and with what restitution and friction: the ground
// with every moving body, and the pairs the case's [[contact]] entries name. Scene data,
// read the same way by the course methods, the reference and the engine adapters (which
// detect the contacts themselves).
#pragma once

#include <optional>
#include <vector>

#include "model/world.hpp"

namespace bb {

/// Two things that may touch: body `a` against body `b`, or against the ground (b = -1).
struct ContactPair {
  int a = -1;
  int b = -1;  ///< -1: the ground; a fixed body, when one takes part, is always b; else a box is
  double restitution = 0.0;
  double friction_static = 0.0;
  double friction_kinetic = 0.0;
  bool ground() const { return b < 0; }
};

/// Every pair that can touch in a fixed order: the ground's first, then the pairs [[contact]]
/// entries name one by one, then those ["*"] adds. A pair named by itself takes its own
/// values whatever comes before or after it; two fixed bodies never touch. (The loader
/// refuses a pair named twice.)
std::vector<ContactPair> contact_pairs(const World& scene);

/// Body `body`'s pair with the ground, as contact_pairs() gives it; nullopt when the scene
/// has no ground or the body is fixed.
std::optional<ContactPair> ground_pair(const World& scene, int body);

/// Whether some body's contact with the ground has friction.
bool ground_rubs(const World& scene);

}  // namespace bb
