// When the course's collision test surely catches a ball flying at a thin fixed box (seed
// section 4, the tunnelling case), derived from the course's own code: ContactPhases::detect
// (course_step.cpp) looks for an overlap only at the end of each step (gap < 0), and
// resolve_fixed (collision_rules.cpp) turns the ball back along the normal of the box's face
// nearest its centre (contact::sphere_box). Along the ball's path, with h the box's half
// thickness and r the ball's radius, a step that ends with the centre in (-(h + r), 0) from
// the box's middle turns it back the way it came; one that ends in [0, h + r) pushes it out
// of the far face (it passes, caught or not); and steps that jump the whole window never see
// the box. At a constant speed v the steps end v dt apart, so one ends in the near half for
// certain exactly when v dt < h + r: half of (the box's thickness + the ball's diameter), not
// all of it. Past that bound the outcome hangs on where the steps happen to land.
#pragma once

#include <optional>

#include "model/world.hpp"

namespace bb {

/// The largest step (s) at which the course's test surely turns the ball back, (h + r) / v,
/// for a world the derivation covers: one moving body, a ball flying at a constant velocity
/// (no gravity, air, springs, impulses or applied forces) along an axis of a fixed box it may
/// touch, its path through the box's face and its start before the near half; nullopt
/// otherwise.
std::optional<double> surely_turned_back_step(const World& world);

}  // namespace bb
