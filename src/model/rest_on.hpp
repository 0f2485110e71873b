// A body placed on the ground or on top of another body (`rest_on` in a [[body]]), and the
// test for one that starts near the ground but not on it: such a start is a mistake of a few
// micrometres that sends a box to the reference's fallback ("does not start flat on a face on
// the ground").
#pragma once

#include <string>

#include "model/world.hpp"

namespace bb {

/// A gap or overlap below this fraction of a box's size (its reach along the ground's
/// normal), and above kOverlapRounding, is a box meant to rest on the ground but not on it.
inline constexpr double kNearMissFraction = 1e-3;

/// Below this turn (radians) from flat, a box on the ground is meant to lie flat on a face.
inline constexpr double kNearMissTilt = 1e-3;

/// Puts `body` on `ground`: its centre at its reach along the normal from the ground's
/// plane (a sphere's radius, a box's half height, 0 for a point), above the foot of its
/// given position on the plane (the position's part along the plane is kept, its height
/// along the normal replaced). A box is first turned so that its y axis is the normal
/// (the shortest turn from +y), so its -y face lies on the plane.
void place_on_ground(Body& body, const Ground& ground);

/// Puts `body` on top of `below`, along `up` (unit, against gravity): its part across `up`
/// is kept and its height set so that it touches `below` from above. A box is first turned
/// by the shortest turn taking its y axis to `up`. `below` is a sphere, or a box with a face
/// turned to `up` (cosine within 1e-12 of 1), and `body`'s centre must be over it (over the
/// box's top face; within the spheres' summed radii of the sphere's centre; a box over a
/// sphere: the sphere's top under its bottom face). Returns why it cannot, "" when placed.
std::string place_on_body(Body& body, const Body& below, const Vec3& up);

/// What is wrong with `body`'s start near `ground` ("starts 2.4e-06 m above the ground",
/// "... inside ...", "is turned 0.0007 degrees from flat on the ground"), or "" when it
/// rests on it to rounding, is clearly apart from it, or is not a box (a ball a hair off the
/// ground lands on it; a box is lost to the reference, which needs it flat on a face).
std::string near_ground_miss(const Body& body, const Ground& ground);

}  // namespace bb
