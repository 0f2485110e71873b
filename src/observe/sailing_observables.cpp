// The sailing observables (seed section 9), each at the last sample, from the boat's own
// heading there (its x axis): forward_speed (m/s) along the heading, drift_angle (degrees)
// between the velocity and the heading (none for a boat at rest), made_good_upwind (m) the way made
// against the wind since the start; and, for anything the wind carries (the wind panel of section
// 8), downwind_distance (m) the way made with it. One registry line each.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/text.hpp"
#include "observe/observable_measure.hpp"
#include "observe/stop_observables.hpp"
#include "physics/boat_frame.hpp"

namespace bb {

ObservableValue measure_forward_speed(const Scene&, const Observe& observe,
                                      const Trajectory& trajectory, const EventTrace*) {
  const BodyState& last = trajectory.states.back()[observe.body];
  return {last.velocity.dot(boat_frame(last.orientation).ahead), ""};
}

namespace {

/// Why a boat moving at `speed` (m/s) on the water at the last sample has no direction of
/// motion to measure: slower than the case's rest_speed, else than kRestShare of the larger
/// of the wind's speed and the fastest the boat moved at the samples (an edge-on sail's
/// rounding, a calm); nullopt when it is faster.
std::optional<std::string> at_rest(const Scene& scene, const Observe& observe,
                                   const Trajectory& trajectory, double speed) {
  std::string why;
  double rest = 0.0;
  if (const std::optional<double> stated = stated_rest_speed(scene, observe.body)) {
    rest = *stated;
    why = "the case's 'rest_speed'";
  } else {
    const double wind = scene.air ? scene.air->wind.norm() : 0.0;
    double fastest = 0.0;
    for (const State& s : trajectory.states)
      fastest = std::max(fastest, s[observe.body].velocity.norm());
    rest = kRestShare * std::max(wind, fastest);
    why = wind >= fastest ? "a thousandth of the wind's " + short_number(wind) + " m/s"
                          : "a thousandth of its fastest, " + short_number(fastest) + " m/s";
  }
  if (speed > rest) return std::nullopt;
  if (speed == 0.0) return "does not apply: the boat does not move: it has no direction of motion";
  return "does not apply: the boat moves at " + short_number(speed) +
         " m/s, no faster than its rest speed " + short_number(rest) + " m/s (" + why +
         "): at rest, its direction of motion is its rounding's";
}

}  // namespace

ObservableValue measure_drift_angle(const Scene& scene, const Observe& observe,
                                    const Trajectory& trajectory, const EventTrace*) {
  const BodyState& last = trajectory.states.back()[observe.body];
  const BoatFrame frame = boat_frame(last.orientation);
  const double ahead = last.velocity.dot(frame.ahead), across = last.velocity.dot(frame.across);
  if (auto why = at_rest(scene, observe, trajectory, std::hypot(ahead, across)))
    return {std::nullopt, *why};
  return {std::atan2(std::abs(across), ahead) * 180.0 / std::numbers::pi, ""};
}

namespace {

/// How far the body moved from the first sample to the last along the wind (+1) or against
/// it (-1); nullopt without a wind.
ObservableValue moved_along_wind(const Scene& scene, const Observe& observe,
                                 const Trajectory& trajectory, double sign) {
  if (!scene.air || scene.air->wind.norm() == 0.0)
    return {std::nullopt, "no wind: the case's [air] has no 'wind'"};
  const Vec3 along = sign * scene.air->wind.normalized();
  const Vec3 moved = trajectory.states.back()[observe.body].position -
                     trajectory.states.front()[observe.body].position;
  return {moved.dot(along), ""};
}

}  // namespace

ObservableValue measure_made_good_upwind(const Scene& scene, const Observe& observe,
                                         const Trajectory& trajectory, const EventTrace*) {
  return moved_along_wind(scene, observe, trajectory, -1.0);
}

ObservableValue measure_downwind_distance(const Scene& scene, const Observe& observe,
                                          const Trajectory& trajectory, const EventTrace*) {
  return moved_along_wind(scene, observe, trajectory, 1.0);
}

}  // namespace bb
