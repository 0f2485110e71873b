// How deep bodies start inside the ground or inside each other. A backend cannot resolve a
// start inside (the reference lets such a ball fall through the ground), so the loader
// refuses any overlap deeper than rounding, at load and at every point of a [[sweep]].
#pragma once

#include "model/world.hpp"

namespace bb {

/// Overlaps up to this depth, metres, are rounding: a body placed by hand on a tilted
/// ground, or resting on another, lands within it. Positions are bounded (1e6 m, see
/// vector_limits.hpp), where a double's rounding is 1.2e-10 m, so the bound holds at any
/// position; it is also the distance at which the course methods count a body as touching.
inline constexpr double kOverlapRounding = 1e-9;

/// How far `body` reaches below the surface of `ground`, metres; zero or less when clear.
/// A point is a sphere of radius 0.
double ground_depth(const Body& body, const Ground& ground);

/// How far `a` and `b` reach into each other, metres (the least push that separates them);
/// zero or less when apart.
double overlap_depth(const Body& a, const Body& b);

}  // namespace bb
