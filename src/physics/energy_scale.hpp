// How much energy a scene can put into motion over a run, from the case alone: the scale a
// run's energy is judged against (divergence, stability). A run whose energy rises far
// above it has created energy no part of the scene could give.
#pragma once

#include <string>
#include <vector>

#include "model/world.hpp"

namespace bb {

struct EnergyScale {
  double kinetic = 0.0;   ///< J: the bodies' kinetic energy at the start, spin included
  double gravity = 0.0;   ///< J: the most potential energy gravity can release over the run
  double forces = 0.0;    ///< J: what the force terms can supply (ForceTerm::supply)
  double impulses = 0.0;  ///< J: the most the case's impulses can give
  /// J: every body lifted and moved by its own size over the run, the scale of a scene at
  /// rest (a contact's jitter is judged against it)
  double rest = 0.0;
  double total() const { return kinetic + gravity + forces + impulses + rest; }
  /// "11.8 J (gravity 10.3 J, springs and other forces 1.5 J)": the total and its parts.
  std::string describe() const;
};

/// The scale of `scene` over a run of `duration` seconds. Gravity releases at most, per
/// moving body, m g times the deepest it can fall: no deeper than free fall over the run, than
/// its height above a level ground, than a hinge's reach below its anchor, or than its
/// tether allows (the shortest chain of springs to a fixed body, each spring stretched as far
/// as the whole scale could stretch it; the scale and the stretch are solved together).
EnergyScale energy_scale(const World& scene, double duration);

/// Per body, the fastest it can plausibly move (m/s): its speed at the start, free fall over
/// the whole run, and the scale's whole energy given to it alone. Zero for a fixed body.
std::vector<double> speed_bounds(const World& scene, const EnergyScale& scale, double duration);

}  // namespace bb
