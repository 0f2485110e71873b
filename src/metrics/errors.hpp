// Error norms of a run against the reference at the same sample times.
#pragma once

#include <vector>

#include "metrics/trajectory.hpp"
#include "study/scene.hpp"

namespace bb {

/// One body's errors against the reference over the samples.
struct BodyErrors {
  double position_max = 0.0;    ///< metres
  double position_rms = 0.0;    ///< metres, RMS over the samples
  double position_final = 0.0;  ///< metres, at the last sample
  double velocity_max = 0.0;    ///< metres per second
};

/// Worst body, over every sample (docs/design.md, "Results").
struct ErrorMetrics {
  double position_max = 0.0;    ///< metres
  double position_rms = 0.0;    ///< metres, RMS over samples of the worst body
  double position_final = 0.0;  ///< metres, at the last sample
  double velocity_max = 0.0;    ///< metres per second
  double energy_max = 0.0;      ///< max |E - E_ref| / max(|E_ref(0)|, 1 J)

  /// Each body's, in the scene's order (the energy is the whole scene's): the figures above
  /// are their largest. Empty for errors read from a file that did not keep them.
  std::vector<BodyErrors> bodies;

  /// The metric called `name`; throws std::invalid_argument for an unknown one.
  double get(const std::string& name) const;
  /// The body whose position_max is the largest (the first of equals); -1 with no bodies.
  int worst_body() const;
};

/// Requires both trajectories to cover the same sample times.
ErrorMetrics compare(const Scene& scene, const Trajectory& run, const Trajectory& reference);

/// Largest position difference (m) between two trajectories on the same samples.
double max_position_difference(const Trajectory& a, const Trajectory& b);

/// The largest difference of each state component between two trajectories on the same
/// samples (the first samples of the shorter), worst body.
struct StateDifference {
  double position = 0.0;     ///< m
  double velocity = 0.0;     ///< m/s
  double orientation = 0.0;  ///< rad: the angle of the rotation from one to the other
  double spin = 0.0;         ///< rad/s, angular velocity
};
StateDifference max_state_difference(const Trajectory& a, const Trajectory& b);

}  // namespace bb
