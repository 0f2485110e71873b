// The sailing observables (seed section 9), each at the last sample, from the boat's own
// heading there (its x axis): forward_speed (m/s) along the heading, drift_angle (degrees)
// between the velocity and the heading, made_good_upwind (m) the way made against the wind
// since the start; and, for anything the wind carries (the wind panel of section 8),
// downwind_distance (m) the way made with it. One registry line each.
#include <cmath>
#include <numbers>

#include "observe/observable_measure.hpp"
#include "physics/boat_frame.hpp"

namespace bb {

ObservableValue measure_forward_speed(const Scene&, const Observe& observe,
                                      const Trajectory& trajectory, const EventTrace*) {
  const BodyState& last = trajectory.states.back()[observe.body];
  return {last.velocity.dot(boat_frame(last.orientation).ahead), ""};
}

ObservableValue measure_drift_angle(const Scene&, const Observe& observe,
                                    const Trajectory& trajectory, const EventTrace*) {
  const BodyState& last = trajectory.states.back()[observe.body];
  if (last.velocity.norm() == 0.0) return {std::nullopt, "the boat does not move"};
  const BoatFrame frame = boat_frame(last.orientation);
  return {std::atan2(std::abs(last.velocity.dot(frame.across)), last.velocity.dot(frame.ahead)) *
              180.0 / std::numbers::pi,
          ""};
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
